// SPDX-License-Identifier: GPL-3.0-or-later
#include "station.h"

#include "alarmmonitor.h"
#include "dopplerradio.h"
#include "localstationface.h"
#include "schedulerunner.h"
#include "passrecorder.h"
#include "remoteoperation.h"

#include "bridge/rotctldserver.h"
#include "face/schedulerequest.h"
#include "input/finitenumber.h"
#include "radio/transpondersources.h"
#include "records/passrecordstore.h"
#include "session/controllerrotors.h"
#include "session/movewatch.h"
#include "session/rotatorsession.h"
#include "session/stopbeforeexit.h"
#include "sky/elementage.h"
#include "sky/elementsetsources.h"
#include "tracking/passrunner.h"
#include "tracking/simulatorpace.h"
#include "tracking/stationclock.h"
#include "tracking/tracktarget.h"
#include "transport/sharedline.h"

#include <QSettings>

#include <cmath>

namespace slew::station {

using session::RotatorSession;

namespace {

StationOptions windowOptions()
{
    StationOptions options;
    options.followControllerRotors = true;
    return options;
}

} // namespace

Station::Station(QObject *parent) : Station(windowOptions(), parent) {}

Station::Station(const StationOptions &options, QObject *parent) : QObject(parent)
{
    QList<int> numbers = options.rotors;
    if (!numbers.isEmpty()) {
        m_line = std::make_unique<transport::SharedLine>(options.sharedLineUri);
        if (!m_line->isValid()) {
            m_error = m_line->error();
            m_line.reset();
            numbers.clear(); // no rotors at all: nothing would reach a line
        }
    } else {
        numbers = {0};
    }
    if (m_error.isEmpty()) {
        for (int n : numbers)
            addRotor(n, options);
    }
    // Offline first: nothing is read or fetched until a face asks.
    m_elementSets = std::make_unique<sky::ElementSetSources>(sky::elementSetCacheDirectory());
    m_transponders = std::make_unique<radio::TransponderSources>(radio::transponderCacheDirectory());
    m_clock = std::make_unique<tracking::StationClock>();
    m_records = std::make_unique<records::PassRecordStore>();
    if (m_rotors.empty())
        return;
    RotatorSession *first = session();
    // Before the first connection: a multi-rotor controller's line is shared
    // from the start.
    if (options.followControllerRotors && !m_line)
        m_controllerRotors = std::make_unique<session::ControllerRotors>(first);
    m_moveWatch = std::make_unique<session::MoveWatch>(first);
    m_pace = std::make_unique<tracking::SimulatorPace>(first, m_clock.get());
    m_runner = std::make_unique<tracking::PassRunner>(first);
    m_radio = std::make_unique<DopplerRadio>(first, m_runner.get(), m_clock.get());
    m_schedule = std::make_unique<ScheduleRunner>(first, m_runner.get(), m_clock.get());
    // New elements make a new plan (the schedule takes each target's newest).
    connect(m_elementSets.get(), &sky::ElementSetSources::setsChanged, m_schedule.get(),
            [this] { m_schedule->updateElements(m_elementSets->sets()); });
    m_recorder = std::make_unique<PassRecorder>(first, m_runner.get(), m_radio.get(), m_clock.get());
    m_recorder->setStore(m_records.get());
    // A pass the schedule left out is in the record too, with why.
    connect(m_schedule.get(), &ScheduleRunner::passDropped, m_recorder.get(), [this](const schedule::ScheduledPass &p) {
        if (const std::optional<tracking::TrackTarget> target = m_schedule->targetNamed(p.target))
            m_recorder->recordDropped(*target, p.pass, p.why);
    });
    wireTracking();
    m_face = std::make_unique<LocalStationFace>(this);
}

Station::~Station()
{
    m_face.reset(); // it follows every other part
    if (m_schedule)
        m_schedule->stop(tr("the station is closing"));
    m_remote.reset(); // it follows every other part
    if (m_runner && m_runner->isRunning())
        m_runner->stop(tr("the station is closing"));
    m_recorder.reset(); // it follows the radio and the runner
    m_radio.reset(); // it follows the runner, which goes next
}

void Station::addRotor(int number, const StationOptions &options)
{
    Rotor &rotor = m_rotors.emplace_back();
    rotor.number = number;
    rotor.session = std::make_unique<RotatorSession>();
    RotatorSession *s = rotor.session.get();
    RotatorSession::Options sessionOptions = s->options();
    sessionOptions.autoReconnect = options.autoReconnect;
    s->setOptions(sessionOptions);
    if (options.profile)
        s->setProfile(*options.profile);
    if (m_line)
        s->setLinkMaker([line = m_line.get()](const QString &uri) { return line->makeLink(uri); });
    rotor.server = std::make_unique<bridge::RotctldServer>(s);
    rotor.alarms = std::make_unique<AlarmMonitor>(s);
}

void Station::wireTracking()
{
    bridge::RotctldServer *server = this->server();
    // While Slew tracks, trackers on the rotctld port are held off...
    connect(m_runner.get(), &tracking::PassRunner::activeChanged, this, [this, server](bool active) {
        if (active)
            server->holdRemote(tr("Slew's own tracking"));
        else
            server->releaseRemote();
        emit trackingChanged(active);
    });
    // ...and while a remote tracker steers, Slew's own tracking waits.
    m_runner->setOtherSteering([this] { return otherSteering(); });
}

int Station::rotorNumber(int index) const
{
    return index >= 0 && index < rotorCount() ? m_rotors[size_t(index)].number : -1;
}

RotatorSession *Station::session(int index) const
{
    return index >= 0 && index < rotorCount() ? m_rotors[size_t(index)].session.get() : nullptr;
}

bridge::RotctldServer *Station::server(int index) const
{
    return index >= 0 && index < rotorCount() ? m_rotors[size_t(index)].server.get() : nullptr;
}

AlarmMonitor *Station::alarms(int index) const
{
    return index >= 0 && index < rotorCount() ? m_rotors[size_t(index)].alarms.get() : nullptr;
}

QList<RotatorSession *> Station::everySession() const
{
    QList<RotatorSession *> sessions;
    for (const Rotor &rotor : m_rotors)
        sessions.append(rotor.session.get());
    if (m_controllerRotors) {
        for (RotatorSession *other : m_controllerRotors->rotors()) {
            if (!sessions.contains(other))
                sessions.append(other);
        }
    }
    return sessions;
}

QString Station::rotorUri(int index) const
{
    const RotatorSession *s = session(index);
    if (!s)
        return {};
    return m_line ? transport::SharedLine::rotorUri(m_line->uri(), rotorNumber(index)) : s->profile().uri;
}

void Station::connectRotators()
{
    for (int i = 0; i < rotorCount(); ++i)
        session(i)->connectTo(rotorUri(i));
}

void Station::disconnectRotators()
{
    for (Rotor &rotor : m_rotors) {
        rotor.alarms->expectDisconnect();
        rotor.session->disconnectFromRotator();
    }
}

session::CommandResult Station::stop(const QString &cause)
{
    if (m_rotors.empty())
        return session::CommandResult{m_error};
    session::CommandResult result = session()->stop(cause);
    for (size_t i = 1; i < m_rotors.size(); ++i) {
        if (m_rotors[i].session->isConnected())
            m_rotors[i].session->stop(cause);
    }
    if (m_controllerRotors)
        m_controllerRotors->stopOthers(cause);
    // The operator stays in charge: after a local Stop, trackers may not
    // move the rotator until the operator hands control back.
    for (Rotor &rotor : m_rotors) {
        if (rotor.server->isListening())
            rotor.server->holdRemote();
    }
    if (!m_operatorHolds) {
        m_operatorHolds = true;
        emit operatorHoldChanged(true);
    }
    return result;
}

void Station::handControlBack()
{
    for (Rotor &rotor : m_rotors)
        rotor.server->releaseRemote();
    if (m_operatorHolds) {
        m_operatorHolds = false;
        emit operatorHoldChanged(false);
    }
}

bool Station::startRemote(const RemoteOptions &options, QString *error)
{
    if (m_remote)
        return true;
    if (m_rotors.empty()) {
        *error = m_error;
        return false;
    }
    auto remote = std::make_unique<RemoteOperation>(this, options);
    if (!remote->start(error))
        return false;
    m_remote = std::move(remote);
    return true;
}

QString Station::otherSteering() const
{
    if (m_rotors.empty())
        return {};
    const QString peer = server()->remoteSteering();
    return peer.isEmpty() ? peer : tr("remote tracker %1").arg(peer);
}

face::StationFace *Station::face() const
{
    return m_face.get();
}

QString Station::othersSteeringRefusal(QString other)
{
    other[0] = other[0].toUpper();
    return tr("%1 is steering the rotator: stop it (or Stop, which holds remote trackers off) "
              "before Slew tracks, or the two will fight")
        .arg(other);
}

face::Outcome Station::track(const tracking::TrackTarget &target, double minElevationDeg)
{
    if (!m_runner)
        return face::Outcome::refused(m_error);
    if (!m_place)
        return face::Outcome::refused(tr("tracking needs the station's place"));
    if (target.kind == tracking::TrackTarget::Kind::Satellite) {
        const QString old = sky::elementsTooOld(target.elements, m_clock->nowJulian(), m_runner->elementAgeLimitDays(),
                                                tr("now"));
        if (!old.isEmpty())
            return face::Outcome::refused(
                tr("%1 is not tracked: %2; refresh the element sets or raise the limit").arg(target.name(), old));
    }
    if (QString other = otherSteering(); !other.isEmpty()) {
        other[0] = other[0].toUpper();
        return face::Outcome::refused(othersSteeringRefusal(other));
    }
    m_schedule->stop(tr("one target is tracked instead"));
    m_runner->start(target, *m_place, minElevationDeg, m_clock.get());
    return face::Outcome::done();
}

void Station::setElementAgeLimitDays(double days)
{
    if (m_runner && std::isfinite(days) && days > 0)
        m_runner->setElementAgeLimitDays(days);
}

double Station::elementAgeLimitDays() const
{
    return m_runner ? m_runner->elementAgeLimitDays() : sky::kElementAgeLimitDays;
}

face::Outcome Station::runSchedule(const QList<tracking::TrackTarget> &targets, const ScheduleOptions &options)
{
    if (!m_runner)
        return face::Outcome::refused(m_error);
    if (!m_place)
        return face::Outcome::refused(tr("a schedule needs the station's place"));
    if (targets.isEmpty())
        return face::Outcome::refused(tr("a schedule needs at least one target"));
    if (const QString fault = scheduleOptionsFault(options); !fault.isEmpty())
        return face::Outcome::refused(fault);
    if (const QString other = otherSteering(); !other.isEmpty())
        return face::Outcome::refused(othersSteeringRefusal(other));
    // The same schedule with other targets (one added, the order changed)
    // is planned again with them: a pass in progress is kept.
    if (m_schedule->isRunning() && m_schedule->options() == options) {
        m_schedule->setTargets(targets);
        return face::Outcome::done();
    }
    if (m_runner->isRunning())
        m_runner->stop(tr("a schedule is run instead"));
    m_schedule->start(targets, *m_place, options);
    return face::Outcome::done();
}

face::Outcome Station::untrack(const QString &why)
{
    const bool tracking = (m_schedule && m_schedule->isRunning()) || (m_runner && m_runner->isRunning());
    if (m_schedule)
        m_schedule->stop(why);
    if (m_runner)
        m_runner->stop(why);
    return tracking ? face::Outcome::done() : face::Outcome::refused(tr("Slew is not tracking"));
}

face::Outcome Station::stopSchedule(const QString &why)
{
    if (!m_schedule || !m_schedule->isRunning())
        return face::Outcome::refused(tr("no schedule is running"));
    m_schedule->stop(why);
    return face::Outcome::done();
}

face::Outcome Station::holdRadio(bool held)
{
    if (!m_radio)
        return face::Outcome::refused(m_error);
    m_radio->holdControl(held);
    return face::Outcome::done();
}

QString Station::openPassRecords(const QString &path, int keepDays, bool readWhenTaken)
{
    // A record under way would be finished in a file it was not begun in.
    if (m_recorder && m_recorder->currentRecord())
        return tr("a pass is being recorded now: open the pass records between passes");
    const QString file = path.isEmpty() ? records::PassRecordStore::defaultPath() : path;
    m_records->setKeepDays(keepDays);
    QString error;
    if (m_records->open(file, records::PassRecordStore::Access::Record, &error))
        return {};
    QString ignored;
    if (readWhenTaken && m_records->takenByAnother()
        && m_records->open(file, records::PassRecordStore::Access::Read, &ignored))
        return tr("%1; this one shows its passes and records none").arg(error);
    return error;
}

void Station::setPlace(const std::optional<sky::Site> &place)
{
    m_place = place;
    emit placeChanged(m_place);
}

QString Station::restoreSavedPlace()
{
    sky::Site saved;
    QString ignored;
    const QSettings settings;
    const QString text = settings.value(QLatin1String(sky::kSiteSettingsKey)).toString();
    if (text.isEmpty() || !sky::parseSite(text, &saved, &ignored))
        return {};
    QString problem;
    const QString horizon = settings.value(QLatin1String(sky::kHorizonSettingsKey)).toString();
    if (!horizon.isEmpty()) {
        const sky::HorizonFile read = sky::readHorizonFile(horizon);
        if (read.mask)
            saved.horizon = read.mask;
        else
            problem = tr("the station's horizon mask: %1; the horizon is taken as flat").arg(read.error);
    }
    setPlace(saved);
    return problem;
}

void Station::shutdown(const QString &why)
{
    if (m_shuttingDown)
        return;
    m_shuttingDown = true;
    if (m_schedule)
        m_schedule->stop(why);
    if (m_runner)
        m_runner->stop(why);
    // No tracker moves a rotor again meanwhile.
    for (Rotor &rotor : m_rotors)
        rotor.server->close();
    const QList<RotatorSession *> sessions = everySession();
    // Every rotor's stop, and the remote's goodbye (its last state and
    // online = false), one more so none can end it before all have begun.
    m_stillStopping = int(sessions.size()) + 1;
    if (m_remote) {
        ++m_stillStopping;
        connect(m_remote.get(), &RemoteOperation::closed, this, &Station::stoppedOne, Qt::SingleShotConnection);
        m_remote->close(why);
    }
    for (RotatorSession *s : sessions) {
        s->reportHeldBack(); // the journal gets the count of what it was spared
        const bool sent = session::stopThenCall(*s, tr("Slew is ending: %1").arg(why), this, [this] { stoppedOne(); });
        for (const Rotor &rotor : m_rotors) {
            if (sent && rotor.session.get() == s)
                emit exitStopSent(rotor.number);
        }
    }
    stoppedOne();
}

void Station::stoppedOne()
{
    if (--m_stillStopping == 0)
        emit shutDown();
}

} // namespace slew::station
