// SPDX-License-Identifier: GPL-3.0-or-later
#include "passrunner.h"

#include "rotatorreach.h"
#include "skytrack.h"

#include "session/rotatorsession.h"
#include "sky/passes.h"
#include "sky/utctime.h"

#include <QFutureWatcher>
#include <QtConcurrent/QtConcurrentRun>

namespace slew::tracking {

using session::RotatorSession;

namespace {
constexpr double kLookAheadDays = 2.0;
constexpr double kLookBackDays = 1.0 / 24.0; // where a pass under way rose: any LEO pass within the hour
constexpr int kRetryMs = 3600 * 1000; // no pass in two days: look again in an hour
constexpr int kOtherQuietSeconds = 10;  // as RotctldServer::kSteeringQuietMs
constexpr int kOtherLookAgainMs = 1000;
}

PassRunner::PassRunner(RotatorSession *session, QObject *parent) : QObject(parent), m_session(session), m_tracker(session)
{
    m_retry.setSingleShot(true);
    connect(&m_retry, &QTimer::timeout, this, &PassRunner::nextPass);
    connect(&m_tracker, &Tracker::stateChanged, this, &PassRunner::onTrackerState);
    connect(&m_tracker, &Tracker::heldForPosition, this,
            [this](const QString &why) { emit logLine(tr("the antenna waits: %1").arg(why)); });
    connect(session, &RotatorSession::stateChanged, this, [this](RotatorSession::State s) {
        // The link is back: the next pass (or the rest of this one).
        if (s == RotatorSession::State::Connected && m_running && !isActive())
            QMetaObject::invokeMethod(this, &PassRunner::nextPass, Qt::QueuedConnection);
    });
}

PassRunner::~PassRunner()
{
    cancelPlanning();
}

void PassRunner::cancelPlanning()
{
    if (m_planStop)
        m_planStop->store(true);
    m_planStop.reset();
}

QString PassRunner::isoTime(double julian)
{
    return sky::isoUtc(julian);
}

bool PassRunner::isActive() const
{
    return m_tracker.state() == Tracker::State::Waiting || m_tracker.state() == Tracker::State::Tracking;
}

void PassRunner::start(const TrackTarget &target, const sky::Site &station, double minElevationDeg,
                       const StationClock *clock)
{
    m_one.reset();
    begin(target, station, minElevationDeg, clock);
}

void PassRunner::startOne(const TrackTarget &target, const sky::Site &station, double minElevationDeg,
                          const StationClock *clock, double fromJulian, double untilJulian)
{
    m_one = std::pair{fromJulian, untilJulian};
    begin(target, station, minElevationDeg, clock);
}

void PassRunner::endOne(OneEnd end, const QString &why)
{
    m_running = false;
    m_planning = false;
    disconnect(m_clockChanged);
    disconnect(m_clockStepped);
    cancelPlanning();
    ++m_generation;
    m_retry.stop();
    m_one.reset();
    emit onePassEnded(end, why);
}

void PassRunner::begin(const TrackTarget &target, const sky::Site &station, double minElevationDeg,
                       const StationClock *clock)
{
    m_target = target;
    m_sky.emplace(target);
    m_station = station;
    m_minElevation = minElevationDeg;
    m_clock = clock;
    disconnect(m_clockChanged);
    disconnect(m_clockStepped);
    m_clockChanged = connect(clock, &StationClock::changed, this, [this] {
        if (m_one) {
            // The schedule was made for the old time: it plans again.
            m_tracker.stopTracking(tr("the station clock was changed"));
            endOne(OneEnd::ClockChanged, tr("the station clock was changed"));
            return;
        }
        startAfresh(tr("the station clock was changed"));
    });
    // A paused rehearsal stepped on: the tracker looks at the new instant at once.
    m_clockStepped = connect(clock, &StationClock::stepped, &m_tracker, &Tracker::lookAgain);
    m_running = true;
    m_planning = false;
    cancelPlanning();
    m_waitingFor.clear();
    ++m_generation;
    if (m_one)
        emit logLine(tr("tracking %1 from %2 to %3").arg(target.name(), isoTime(m_one->first), isoTime(m_one->second)));
    else
        emit logLine(tr("tracking %1%2%3")
                         .arg(target.name(), minElevationDeg > 0 ? tr(", passes that climb to %1°").arg(minElevationDeg) : QString())
                         .arg(clock->isRehearsal() ? tr(", rehearsal clock from %1 at %2x").arg(isoTime(clock->nowJulian())).arg(clock->rate())
                                                   : QString()));
    if (m_session->isConnected())
        nextPass();
}

void PassRunner::stop(const QString &why)
{
    if (!m_running)
        return;
    if (m_one) {
        m_tracker.stopTracking(why);
        if (m_running) // the tracker was not active: nothing said it yet
            endOne(OneEnd::Stopped, why);
        return;
    }
    m_running = false;
    m_planning = false;
    disconnect(m_clockChanged);
    disconnect(m_clockStepped);
    cancelPlanning();
    ++m_generation;
    m_retry.stop();
    m_tracker.stopTracking(why); // what follows the end (the pass's record) still sees the pass
    m_pass.reset();
}

void PassRunner::startAfresh(const QString &why)
{
    if (!m_running)
        return;
    emit logLine(tr("planning again: %1").arg(why));
    // Not running while the tracker lets go, so its Idle is not taken for
    // the end of tracking; start() runs again at once.
    m_running = false;
    m_retry.stop();
    m_tracker.stopTracking(why);
    start(m_target, m_station, m_minElevation, m_clock);
}

void PassRunner::nextPass()
{
    if (!m_running || isActive() || m_planning || !m_session->isConnected())
        return;
    if (const QString other = m_otherSteering ? m_otherSteering() : QString(); !other.isEmpty()) {
        // Said once; looked at again every second, so tracking starts as
        // soon as the other tracker's quiet time is over.
        if (other != m_waitingFor)
            emit logLine(tr("%1 is steering the rotator; tracking waits until it has been quiet for %2 s")
                             .arg(other)
                             .arg(kOtherQuietSeconds));
        m_waitingFor = other;
        m_retry.start(kOtherLookAgainMs);
        return;
    }
    if (!m_waitingFor.isEmpty())
        emit logLine(tr("%1 has been quiet for %2 s: Slew takes the rotator").arg(m_waitingFor).arg(kOtherQuietSeconds));
    m_waitingFor.clear();
    const double now = m_clock->nowJulian();
    if (m_one && now >= m_one->second) {
        endOne(OneEnd::NotFound, tr("its time was over by %1").arg(isoTime(now)));
        return;
    }
    // AOS and LOS at the horizon (or the mask); the minimum elevation keeps
    // the passes that climb to it (sky/passes.h).
    sky::PassWindow window{now, now + kLookAheadDays, 0.0, nullptr, m_minElevation};
    // The schedule's pass: its AOS falls between the times given (a minute's
    // margin for the pass predicted afresh), or it is under way then; never
    // an earlier pass of the same target (one the schedule dropped).
    if (m_one)
        window = sky::PassWindow{m_one->first - 60.0 / sky::kSecondsPerDay, m_one->second, 0.0, nullptr, m_minElevation};
    const std::optional<std::pair<double, double>> one = m_one;
    const RotatorReach reach = reachOf(*m_session);
    PlannerOptions options;
    if (m_session->hasPosition())
        options.startAzimuth = m_session->azimuth();
    m_planning = true;
    const int generation = ++m_generation;
    auto *watcher = new QFutureWatcher<std::optional<PlannedPass>>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, generation, reach, now] {
        watcher->deleteLater();
        if (generation != m_generation)
            return; // stopped or restarted meanwhile
        m_planning = false;
        onPlanned(watcher->result(), reach, now);
    });
    // Everything the worker reads is a copy; the satellite's SGP4 set-up is
    // shared, read-only.
    cancelPlanning();
    m_planStop = std::make_shared<std::atomic<bool>>(false);
    watcher->setFuture(QtConcurrent::run([sky = *m_sky, station = m_station, window, now, reach, options,
                                          stop = m_planStop, one]() mutable {
        window.stop = stop.get();
        if (one)
            return forecastPassBetween(sky, station, window, now, 5.0, one->first, one->second, reach, options,
                                       kLookBackDays);
        // A pass joined under way is recorded and logged as it really is:
        // its AOS and its highest point, which may be behind it.
        return forecastNextPass(sky, station, window, now, 5.0, reach, options, kLookBackDays);
    }));
}

void PassRunner::onPlanned(const std::optional<PlannedPass> &next, const RotatorReach &reach, double plannedAtJulian)
{
    if (!m_running || isActive() || !m_session->isConnected())
        return; // a lost link plans again when it is back
    if (!next && m_one) {
        endOne(OneEnd::NotFound, tr("no pass of %1 above %2° from %3 to %4")
                                     .arg(m_target.name())
                                     .arg(m_minElevation)
                                     .arg(isoTime(m_one->first), isoTime(m_one->second)));
        return;
    }
    if (!next) {
        emit logLine(tr("no pass of %1 above %2° in the next %3 days; looking again in an hour")
                         .arg(m_target.name()).arg(m_minElevation).arg(kLookAheadDays));
        m_retry.start(kRetryMs);
        return;
    }
    const sky::Pass &pass = next->pass;
    if (m_target.kind == TrackTarget::Kind::Satellite) {
        const QString old = sky::elementsTooOld(m_target.elements, pass.aos.julian, m_elementAgeLimitDays, tr("AOS"));
        if (!old.isEmpty()) {
            const QString why = tr("the pass of %1 at %2 is not tracked: %3").arg(m_target.name(), isoTime(pass.aos.julian), old);
            if (m_one) {
                endOne(OneEnd::NotFound, why);
                return;
            }
            if (pass.aos.julian < m_target.elements.epochJulian()) {
                // A rehearsal before the elements' epoch: later passes come
                // nearer to it.
                emit logLine(tr("%1; trying the next one after its LOS").arg(why));
                retryAfter(pass, plannedAtJulian);
                return;
            }
            // Later passes are further still: nothing to wait for.
            const QString end = tr("%1; refresh the element sets or raise the limit").arg(why);
            emit logLine(end);
            stop(end);
            return;
        }
    }
    m_pass = pass;
    if (m_target.isFixed())
        emit logLine(tr("holding %1 until %2").arg(m_target.name(), isoTime(pass.los.julian)));
    else
        emit logLine(tr("next pass: %1, AOS %2 at %3°, highest %4° at %5, LOS %6 at %7°%8")
                     .arg(m_target.name(), isoTime(pass.aos.julian))
                     .arg(pass.aos.azimuthDeg, 0, 'f', 1)
                     .arg(pass.maxElevationDeg(), 0, 'f', 1)
                     .arg(isoTime(pass.tca.julian), isoTime(pass.los.julian))
                     .arg(pass.los.azimuthDeg, 0, 'f', 1)
                     .arg(next->fromJulian > pass.aos.julian ? tr(" (under way: from %1)").arg(isoTime(next->fromJulian))
                                                              : QString()));
    const StationClock *clock = m_clock;
    TrackerSettings settings = trackerSettingsFor(m_session->profile().motion, m_tracker.settings());
    // A fixed target's next stretch follows at once: nothing to park between.
    settings.afterPass = m_target.isFixed() ? TrackerSettings::AfterPass::Stay : m_afterPass;
    m_tracker.setSettings(settings);
    m_pass = pass;
    if (!m_tracker.track(next->points, next->plan, next->fromJulian, reach, [clock] { return clock->nowJulian(); })) {
        if (m_one) {
            endOne(OneEnd::NotFound, tr("cannot track this pass: %1").arg(m_tracker.error()));
            return;
        }
        emit logLine(tr("cannot track this pass: %1; trying the next one after its LOS").arg(m_tracker.error()));
        retryAfter(pass, plannedAtJulian);
    }
}

void PassRunner::retryAfter(const sky::Pass &pass, double plannedAtJulian)
{
    const double wait = (pass.los.julian - plannedAtJulian) * sky::kSecondsPerDay / std::max(1.0, m_clock->rate());
    m_retry.start(int(std::min(wait * 1000.0 + 1000.0, double(kRetryMs))));
}

void PassRunner::onTrackerState(Tracker::State state, const QString &why)
{
    const bool active = holdsRotator();
    if (active != m_wasActive) {
        m_wasActive = active;
        emit activeChanged(active);
    }
    switch (state) {
    case Tracker::State::Waiting:
        // The first word from a new pass is its plan.
        emit logLine(why == m_tracker.plan().describe() ? tr("plan: %1").arg(why) : tr("waiting for AOS: %1").arg(why));
        break;
    case Tracker::State::Tracking:
        emit logLine(tr("AOS: tracking %1").arg(m_target.name()));
        break;
    case Tracker::State::Done: {
        const TrackingFigures &f = m_tracker.figures();
        ++m_passesDone;
        emit logLine(tr("LOS: pointing error RMS %1°, worst %2° over %3 readings from AOS + %4 s; %5 commands "
                        "(%6 a second); the plan predicted worst %7°")
                         .arg(f.rmsDeg, 0, 'f', 3)
                         .arg(f.worstDeg, 0, 'f', 2)
                         .arg(f.samples)
                         .arg(Tracker::kSettleSeconds, 0, 'f', 0)
                         .arg(f.commands)
                         .arg(f.commandsPerSecond(), 0, 'f', 2)
                         .arg(m_tracker.plan().predictedWorstDeg, 0, 'f', 2));
        if (m_one) {
            endOne(OneEnd::Tracked, QStringLiteral("LOS"));
            break;
        }
        QMetaObject::invokeMethod(this, &PassRunner::nextPass, Qt::QueuedConnection);
        break;
    }
    case Tracker::State::Idle:
        if (!m_running)
            break;
        if (m_session->isConnected()) {
            // A stop from anywhere, or a refused point: tracking ends here.
            m_running = false;
            m_retry.stop();
            emit logLine(tr("tracking ended: %1").arg(why));
            if (m_one)
                endOne(OneEnd::Stopped, why);
        } else {
            emit logLine(tr("tracking paused: %1; the next pass is planned when the link is back").arg(why));
        }
        break;
    }
}

} // namespace slew::tracking
