// SPDX-License-Identifier: GPL-3.0-or-later
#include "remotestation.h"

#include "stationtopics.h"

#include <QDateTime>
#include <QRandomGenerator>

#include <cmath>

namespace slew::remote {

RemoteStation::RemoteStation(const MqttSettings &settings, const QString &stationName, QObject *parent)
    : face::StationFace(parent), m_name(stationName), m_client(std::make_unique<MqttClient>(settings))
{
    // Ids of our own on a reply topic every window of this station shares.
    m_idPrefix = QStringLiteral("w%1-").arg(QRandomGenerator::global()->generate() & 0xffffff, 6, 16, QLatin1Char('0'));
    m_client->subscribe(stationFilter(stationName), 1);
    connect(m_client.get(), &MqttClient::messageReceived, this,
            [this](const QString &topic, const QByteArray &payload) { onMessage(topic, payload); });
    connect(m_client.get(), &MqttClient::stateChanged, this, [this](MqttClient::State s, const QString &detail) {
        emit connectionChanged(s, detail);
        updateLive();
    });
    connect(m_client.get(), &MqttClient::publishRefused, this, [this](int mid, const QString &reason) {
        const QString id = m_publishes.take(mid);
        const Pending pending = m_pending.take(id);
        fail(id, pending.command.isEmpty() ? tr("a command") : pending.command,
             tr("the broker refused it (%1): this account may only watch").arg(reason));
    });
    connect(m_client.get(), &MqttClient::subscriptionRefused, this, [this](const QString &filter, const QString &why) {
        refuse(tr("the broker refused to let this account read %1 (%2)").arg(filter, why));
    });
    connect(m_client.get(), &MqttClient::messagesDropped, this, [this](int count, const QString &why) {
        refuse(tr("%1 messages dropped unread: %2").arg(count).arg(why));
    });
    m_liveCheck.setInterval(1000);
    connect(&m_liveCheck, &QTimer::timeout, this, [this] {
        updateLive();
        expireReplies();
    });
    m_liveCheck.start();
    m_jogRenew.setInterval(kJogRenewMs);
    connect(&m_jogRenew, &QTimer::timeout, this, &RemoteStation::renewJog);
}

RemoteStation::~RemoteStation() = default;

bool RemoteStation::open(QString *error)
{
    return m_client->open(error);
}

QString RemoteStation::whyNotLive() const
{
    if (m_client->state() != MqttClient::State::Connected)
        return m_client->problem().isEmpty() ? tr("connecting to the broker")
                                             : tr("the broker: %1").arg(m_client->problem());
    if (!m_state)
        return tr("no word from station %1 yet").arg(m_name);
    if (!m_online)
        return tr("station %1 is offline").arg(m_name);
    if (stateAgeMs() > kStaleAfterMs)
        // The threshold, not a running count: this text is shown where it is
        // not refreshed (the alarm line); the banner gives the state's age.
        return tr("station %1 has said nothing for over %2 s").arg(m_name).arg(kStaleAfterMs / 1000);
    return {};
}

std::optional<qint64> RemoteStation::stationClockMs() const
{
    if (!m_state)
        return std::nullopt;
    if (!m_state->clockMs)
        return QDateTime::currentMSecsSinceEpoch();
    return *m_state->clockMs + qint64(double(stateAgeMs()) * m_state->clockRate);
}

bool RemoteStation::clockJumped(const face::StationState &next) const
{
    if (!m_state)
        return true;
    if (next.clockMs.has_value() != m_state->clockMs.has_value() || next.clockRate != m_state->clockRate)
        return true;
    if (!next.clockMs)
        return false; // the wall clock, on both
    // Carried on from the last state at its rate, a rehearsal's clock is
    // where the next says within a few seconds of delivery.
    const qint64 carried = *m_state->clockMs + qint64(double(next.unixMs - m_state->unixMs) * m_state->clockRate);
    return std::abs(*next.clockMs - carried) > 5000;
}

void RemoteStation::updateLive()
{
    const bool live = whyNotLive().isEmpty();
    if (live == m_live)
        return;
    m_live = live;
    if (!live)
        endJog(); // nothing to renew a lease with
    emit liveChanged(live);
}

model::MoveCheck RemoteStation::previewPointing(double az, double el) const
{
    if (!m_state)
        return {tr("no word from the station yet")};
    const model::MoveGate gate(m_state->limits);
    const std::optional<double> current = m_state->position ? std::optional<double>(m_state->position->x()) : std::nullopt;
    if (m_state->azimuthOnly && el != 0.0)
        return {tr("this rotator turns in azimuth only")};
    return gate.pointing(az, el, current);
}

void RemoteStation::refuse(const QString &what)
{
    ++m_refused;
    if (m_refusals.take(QDateTime::currentMSecsSinceEpoch()))
        emit messageRefused(what);
}

void RemoteStation::onMessage(const QString &topic, const QByteArray &payload)
{
    const std::optional<ParsedTopic> parsed = parseStationTopic(topic);
    if (!parsed || parsed->stationName != m_name)
        return;
    QString why;
    switch (parsed->topic) {
    case StationTopic::Online:
        if (payload != "true" && payload != "false") {
            refuse(tr("%1: neither true nor false").arg(topic));
            return;
        }
        if (m_online != (payload == "true")) {
            m_online = payload == "true";
            emit onlineChanged(m_online);
        }
        updateLive();
        return;
    case StationTopic::State: {
        std::optional<face::StationState> state = parseStationState(payload, &why);
        if (!state) {
            refuse(tr("%1 dropped: %2").arg(topic, why));
            return;
        }
        const bool jumped = clockJumped(*state);
        m_state = std::move(state);
        m_stateAge.start();
        ++m_statesReceived;
        updateLive();
        emit stateChanged(*m_state);
        if (jumped)
            emit skyChanged();
        return;
    }
    case StationTopic::Telemetry: {
        const std::optional<face::TelemetrySample> sample = parseTelemetry(payload, &why);
        if (!sample) {
            refuse(tr("%1 dropped: %2").arg(topic, why));
            return;
        }
        emit telemetryReceived(*sample);
        return;
    }
    case StationTopic::Reply: {
        const std::optional<RemoteReply> reply = parseRemoteReply(payload, &why);
        if (!reply) {
            refuse(tr("%1 dropped: %2").arg(topic, why));
            return;
        }
        if (!m_pending.contains(reply->id))
            return; // another window's
        const Pending pending = m_pending.take(reply->id);
        if (reply->preview)
            emit schedulePreviewed(reply->id, *reply->preview);
        emit replied(reply->id, pending.command, reply->ok, reply->error);
        emit answered(reply->id, reply->ok ? face::Outcome::done() : face::Outcome::refused(reply->error));
        return;
    }
    case StationTopic::Plan: {
        std::optional<face::StationPlan> plan = parseStationPlan(payload, &why);
        if (!plan) {
            refuse(tr("%1 dropped: %2").arg(topic, why));
            return;
        }
        m_plan = std::move(plan);
        emit planChanged(*m_plan);
        return;
    }
    case StationTopic::Schedule: {
        std::optional<face::StationSchedule> schedule = parseStationSchedule(payload, &why);
        if (!schedule) {
            refuse(tr("%1 dropped: %2").arg(topic, why));
            return;
        }
        m_schedule = std::move(schedule);
        emit scheduleChanged(*m_schedule);
        return;
    }
    default:
        return; // commands, ours and others'
    }
}

face::Outcome RemoteStation::send(RemoteCommand command)
{
    command.id = m_idPrefix + QString::number(m_nextId++);
    int mid = 0;
    const MqttMessage message{stationTopic(m_name, StationTopic::Command), encodeRemoteCommand(command), 1, false};
    if (!m_client->publish(message, &mid)) {
        const QString reason = tr("not connected to the broker");
        if (command.kind != RemoteCommand::Kind::Jog)
            emit commandFailed(commandName(command.kind), reason);
        return face::Outcome::refused(reason);
    }
    m_publishes.insert(mid, command.id);
    // A jog's renewals are answered too, but nobody waits for them.
    if (command.kind != RemoteCommand::Kind::Jog || !m_jogRenew.isActive()) {
        Pending pending{commandName(command.kind), {}};
        pending.sent.start();
        m_pending.insert(command.id, pending);
    }
    return face::Outcome::awaiting(command.id);
}

face::Outcome RemoteStation::gotoPosition(double az, double el)
{
    RemoteCommand c;
    c.kind = RemoteCommand::Kind::Goto;
    c.azimuth = az;
    c.elevation = el;
    return send(c);
}

face::Outcome RemoteStation::stop(const QString &)
{
    m_jogRenew.stop();
    RemoteCommand c;
    c.kind = RemoteCommand::Kind::Stop;
    return send(c);
}

face::Outcome RemoteStation::park()
{
    RemoteCommand c;
    c.kind = RemoteCommand::Kind::Park;
    return send(c);
}

face::Outcome RemoteStation::home()
{
    RemoteCommand c;
    c.kind = RemoteCommand::Kind::Home;
    return send(c);
}

face::Outcome RemoteStation::track(const QString &target, double minElevationDeg)
{
    RemoteCommand c;
    c.kind = RemoteCommand::Kind::Track;
    c.target = target.trimmed().left(kLongestTrackTarget);
    c.minElevation = minElevationDeg;
    return send(c);
}

face::Outcome RemoteStation::untrack()
{
    RemoteCommand c;
    c.kind = RemoteCommand::Kind::Untrack;
    return send(c);
}

namespace {

// A schedule's command, run or previewed. Each name cut to what a command
// carries, as track's is; too many is the station's to refuse, as every
// fault of a command is.
RemoteCommand scheduleCommand(RemoteCommand::Kind kind, const QStringList &targets, const face::ScheduleRequest &request)
{
    RemoteCommand c;
    c.kind = kind;
    for (const QString &target : targets)
        c.targets << target.trimmed().left(kLongestTrackTarget);
    c.schedule = request;
    return c;
}

} // namespace

face::Outcome RemoteStation::runSchedule(const QStringList &targets, const face::ScheduleRequest &request)
{
    return send(scheduleCommand(RemoteCommand::Kind::Schedule, targets, request));
}

face::Outcome RemoteStation::previewSchedule(const QStringList &targets, const face::ScheduleRequest &request)
{
    return send(scheduleCommand(RemoteCommand::Kind::SchedulePreview, targets, request));
}

face::Outcome RemoteStation::clearMotionFaults()
{
    RemoteCommand c;
    c.kind = RemoteCommand::Kind::ClearFault;
    return send(c);
}

face::Outcome RemoteStation::stopSchedule()
{
    RemoteCommand c;
    c.kind = RemoteCommand::Kind::Unschedule;
    return send(c);
}

face::Outcome RemoteStation::holdRadio(bool held)
{
    RemoteCommand c;
    c.kind = RemoteCommand::Kind::RadioHold;
    c.held = held;
    return send(c);
}

face::Outcome RemoteStation::startJog(double azSpeed, double elSpeed)
{
    m_jog = RemoteCommand{};
    m_jog.kind = RemoteCommand::Kind::Jog;
    m_jog.azSpeed = std::clamp(azSpeed, -kFastestJog, kFastestJog);
    m_jog.elSpeed = std::clamp(elSpeed, -kFastestJog, kFastestJog);
    m_jog.leaseMs = kJogLeaseMs;
    m_jogRenew.stop();
    const face::Outcome sent = send(m_jog);
    if (sent.isAccepted())
        m_jogRenew.start();
    return sent;
}

void RemoteStation::renewJog()
{
    send(m_jog);
}

void RemoteStation::endJog(const QString &)
{
    if (!m_jogRenew.isActive())
        return;
    m_jogRenew.stop();
    // Zero speeds stop the axes the lease turns, at once rather than when
    // it runs out.
    RemoteCommand c = m_jog;
    c.azSpeed = c.elSpeed = 0;
    send(c);
}

void RemoteStation::expireReplies()
{
    for (auto it = m_pending.begin(); it != m_pending.end();) {
        if (it->sent.elapsed() > kReplyWaitMs) {
            const QString id = it.key(), command = it->command;
            it = m_pending.erase(it);
            fail(id, command, tr("no reply from station %1 within %2 s").arg(m_name).arg(kReplyWaitMs / 1000));
        } else {
            ++it;
        }
    }
    // The broker's ids of what it took long ago are of no more use (only a
    // refusal names one, within a round trip).
    if (m_publishes.size() > 1000)
        m_publishes.clear();
}

void RemoteStation::fail(const QString &id, const QString &command, const QString &why)
{
    emit commandFailed(command, why);
    if (!id.isEmpty())
        emit answered(id, face::Outcome::refused(why));
}

} // namespace slew::remote
