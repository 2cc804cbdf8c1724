// SPDX-License-Identifier: GPL-3.0-or-later
#include "remotecommands.h"

#include "remotejog.h"
#include "schedulepreviewer.h"
#include "schedulerequestoptions.h"
#include "station.h"
#include "targetbyname.h"

#include "session/rotatorsession.h"
#include "tracking/passrunner.h"
#include "tracking/tracktarget.h"

#include <QDateTime>

namespace slew::station {

using remote::RemoteCommand;
using session::CommandResult;

namespace {

qint64 nowMs()
{
    return QDateTime::currentMSecsSinceEpoch();
}

} // namespace

RemoteCommands::RemoteCommands(Station *station, const QList<sky::ElementSet> &elementSets, QObject *parent)
    : QObject(parent), m_station(station), m_elementSets(elementSets), m_jog(new RemoteJog(station->session(), this)),
      m_previewer(new SchedulePreviewer(station, elementSets, this))
{
    connect(m_previewer, &SchedulePreviewer::previewed, this, [this](const QString &id, const face::SchedulePreview &p) {
        emit lateReply(remote::RemoteReply{id, true, {}, p});
    });
    connect(m_previewer, &SchedulePreviewer::refused, this, [this](const QString &id, const QString &why) {
        emit logLine(tr("remote: schedule preview (id %1) refused: %2").arg(id, why));
        emit lateReply(remote::RemoteReply{id, false, why, std::nullopt});
    });
    m_floodEnd.setSingleShot(true);
    m_floodEnd.setInterval(1000);
    connect(&m_floodEnd, &QTimer::timeout, this, &RemoteCommands::endFlood);
    connect(m_jog, &RemoteJog::expired, this, [this](int leaseMs, double az, double el) {
        emit logLine(tr("remote jog (az %1°/s, el %2°/s) not renewed within its lease of %3 ms: stopped")
                         .arg(az, 0, 'f', 1)
                         .arg(el, 0, 'f', 1)
                         .arg(leaseMs));
    });
}

RemoteCommands::~RemoteCommands() = default;

std::optional<remote::RemoteReply> RemoteCommands::handle(const QByteArray &payload)
{
    const qint64 now = nowMs();
    const remote::ParsedCommand parsed = remote::parseRemoteCommand(payload);
    const bool isStop = parsed.command && parsed.command->kind == RemoteCommand::Kind::Stop;
    if (!m_allowance.take(now)) {
        if (m_dropped++ == 0)
            emit logLine(tr("remote: commands are arriving faster than %1 a second: the rest are dropped "
                            "unanswered (a stop still goes out) until they slow down")
                             .arg(kPerSecond));
        ++m_droppedTotal;
        m_floodEnd.start();
        if (isStop)
            stopEveryRotor(tr("a stop over MQTT"));
        return std::nullopt;
    }
    if (!parsed.command) {
        if (m_logAllowance.take(now))
            emit logLine(tr("remote: command refused: %1").arg(input::loggableText(parsed.error)));
        if (parsed.id.isEmpty())
            return std::nullopt;
        return remote::RemoteReply{parsed.id, false, parsed.error, std::nullopt};
    }
    const RemoteCommand &command = *parsed.command;
    if (command.kind == RemoteCommand::Kind::SchedulePreview && m_refusing.isEmpty()) {
        // Moves nothing, under any hold; answered when planned.
        if (m_logAllowance.take(now))
            emit logLine(tr("remote: %1 (id %2)").arg(describe(command), command.id));
        m_previewer->preview(command.id, command.targets, command.schedule);
        return std::nullopt;
    }
    const CommandResult result = obey(command);
    if (m_logAllowance.take(now)) {
        const QString id = command.id.isEmpty() ? QString() : tr(" (id %1)").arg(command.id);
        // Jog renewals are many and alike: only a refusal is worth a line.
        if (!result)
            emit logLine(tr("remote: %1%2 refused: %3").arg(describe(command), id, result.refusal));
        else if (command.kind != RemoteCommand::Kind::Jog)
            emit logLine(tr("remote: %1%2").arg(describe(command), id));
    }
    if (command.id.isEmpty())
        return std::nullopt;
    return remote::RemoteReply{command.id, bool(result), result.refusal, std::nullopt};
}

void RemoteCommands::endFlood()
{
    emit logLine(tr("remote: the flood of commands has ended: %1 dropped").arg(m_dropped));
    m_dropped = 0;
}

QString RemoteCommands::describe(const RemoteCommand &c) const
{
    switch (c.kind) {
    case RemoteCommand::Kind::Goto:
        return tr("go to az %1°, el %2°").arg(c.azimuth, 0, 'f', 1).arg(c.elevation, 0, 'f', 1);
    case RemoteCommand::Kind::Jog:
        return tr("jog az %1°/s, el %2°/s for %3 ms").arg(c.azSpeed, 0, 'f', 1).arg(c.elSpeed, 0, 'f', 1).arg(c.leaseMs);
    case RemoteCommand::Kind::Track:
        return tr("track %1").arg(c.target);
    case RemoteCommand::Kind::Schedule:
        return tr("schedule %1 for %2 h").arg(c.targets.join(QStringLiteral(", "))).arg(c.schedule.hours);
    case RemoteCommand::Kind::SchedulePreview:
        return tr("preview a schedule of %1 for %2 h").arg(c.targets.join(QStringLiteral(", "))).arg(c.schedule.hours);
    case RemoteCommand::Kind::ClearFault:
        return tr("clear the motion guard's fault");
    case RemoteCommand::Kind::RadioHold:
        return c.held ? tr("hold the radio") : tr("hand the radio back to Doppler steering");
    default:
        return remote::commandName(c.kind);
    }
}

QString RemoteCommands::holdOnMoves() const
{
    if (!m_refusing.isEmpty())
        return m_refusing;
    if (m_station->operatorHolds())
        return tr("the operator at the station pressed Stop and holds remote control: remote moves are refused "
                  "until control is handed back");
    const tracking::PassRunner *runner = m_station->passRunner();
    if (runner && runner->holdsRotator())
        return tr("Slew's own tracking of %1 has the rotator: untrack (or Stop) first")
            .arg(runner->target().name());
    return {};
}

CommandResult RemoteCommands::stopEveryRotor(const QString &cause)
{
    m_jog->release();
    session::RotatorSession *first = m_station->session();
    const CommandResult result = first->stop(cause);
    for (int i = 1; i < m_station->rotorCount(); ++i) {
        if (m_station->session(i)->isConnected())
            m_station->session(i)->stop(cause);
    }
    return result;
}

CommandResult RemoteCommands::obey(const RemoteCommand &c)
{
    if (c.kind == RemoteCommand::Kind::Stop)
        return stopEveryRotor(tr("a stop over MQTT")); // always
    if (c.kind == RemoteCommand::Kind::Untrack) {
        if (!m_refusing.isEmpty())
            return CommandResult{m_refusing};
        return CommandResult{m_station->untrack(tr("untracked from the broker")).reason()};
    }
    // Ending a schedule takes a hand off the rotator, as untrack does: no
    // hold stands in its way.
    if (c.kind == RemoteCommand::Kind::Unschedule) {
        if (!m_refusing.isEmpty())
            return CommandResult{m_refusing};
        return CommandResult{m_station->stopSchedule(tr("schedule ended from the broker")).reason()};
    }
    if (c.kind == RemoteCommand::Kind::RadioHold)
        return holdRadio(c.held);
    // Clearing what the motion guard holds moves nothing: an operator who
    // has looked (a camera, someone at the mast) may do it from afar.
    if (c.kind == RemoteCommand::Kind::ClearFault) {
        if (!m_refusing.isEmpty())
            return CommandResult{m_refusing};
        return m_station->session()->clearMotionFaults(tr("a command over MQTT"))
                   ? CommandResult{}
                   : CommandResult{tr("no axis is held by the motion guard")};
    }
    if (const QString hold = holdOnMoves(); !hold.isEmpty()) {
        if (c.kind == RemoteCommand::Kind::Jog)
            m_jog->release();
        return CommandResult{hold};
    }
    session::RotatorSession *s = m_station->session();
    if (c.kind != RemoteCommand::Kind::Jog)
        m_jog->release(); // whatever comes next takes over from the jog
    switch (c.kind) {
    case RemoteCommand::Kind::Goto:
        return s->gotoPosition(c.azimuth, c.elevation);
    case RemoteCommand::Kind::Park:
        return s->park();
    case RemoteCommand::Kind::Home:
        return s->home();
    case RemoteCommand::Kind::Jog:
        return m_jog->jog(c.azSpeed, c.elSpeed, c.leaseMs);
    case RemoteCommand::Kind::Track:
        return track(c);
    case RemoteCommand::Kind::Schedule:
        return schedule(c);
    default:
        return CommandResult{tr("not a command")};
    }
}

CommandResult RemoteCommands::track(const RemoteCommand &c)
{
    QString why;
    const std::optional<tracking::TrackTarget> target = targetByName(*m_station, m_elementSets, c.target, &why);
    if (!target)
        return CommandResult{why};
    return CommandResult{m_station->track(*target, c.minElevation.value_or(0.0)).reason()};
}

CommandResult RemoteCommands::schedule(const RemoteCommand &c)
{
    QString why;
    const std::optional<QList<tracking::TrackTarget>> targets = targetsByName(*m_station, m_elementSets, c.targets, &why);
    if (!targets)
        return CommandResult{why};
    return CommandResult{m_station->runSchedule(*targets, scheduleOptions(c.schedule)).reason()};
}

CommandResult RemoteCommands::holdRadio(bool held)
{
    // Not a move: the holds on remote moves keep a second hand off the
    // rotator, and the radio's hold neither turns the antenna nor fights
    // Slew's tracking (it is what one asks during a pass). Taking the dial
    // is always obeyed, as a stop is; handing it back to the steering,
    // which then tunes (and may key an uplink on) the station's radio, is
    // not while the operator at the station holds remote control.
    if (!m_refusing.isEmpty())
        return CommandResult{m_refusing};
    if (!held && m_station->operatorHolds())
        return CommandResult{tr("the operator at the station pressed Stop and holds remote control: the radio is "
                                "not handed back to Doppler steering from afar until control is handed back")};
    return CommandResult{m_station->holdRadio(held).reason()};
}

} // namespace slew::station
