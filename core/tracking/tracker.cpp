// SPDX-License-Identifier: GPL-3.0-or-later
#include "tracker.h"

#include "stationclock.h"

#include "session/rotatorsession.h"
#include "sky/skyvector.h"

#include <algorithm>
#include <utility>
#include <cmath>

namespace slew::tracking {

using session::RotatorSession;

Tracker::Tracker(RotatorSession *session, QObject *parent) : QObject(parent), m_session(session)
{
    connect(&m_timer, &session::LinkTimer::timeout, this, &Tracker::tick);
    connect(session, &RotatorSession::stopSent, this, [this] {
        if (!m_sending)
            stopTracking(tr("stopped"));
    });
    connect(session, &RotatorSession::stateChanged, this, [this](RotatorSession::State s, const QString &detail) {
        if (s != RotatorSession::State::Connected)
            stopTracking(tr("the link went down: %1").arg(detail));
    });
    connect(session, &RotatorSession::positionChanged, this, &Tracker::onPosition);
}

Tracker::~Tracker() = default;

bool Tracker::track(const QList<SkyPoint> &pass, double aosJulian, const RotatorReach &reach,
                    std::function<double()> now)
{
    PlannerOptions options;
    if (m_session->hasPosition())
        options.startAzimuth = m_session->azimuth();
    return track(pass, planPass(pass, reach, options), aosJulian, reach, std::move(now));
}

bool Tracker::track(const QList<SkyPoint> &pass, const PassPlan &plan, double aosJulian, const RotatorReach &reach,
                    std::function<double()> now)
{
    stopTracking(tr("a new pass"));
    m_error.clear();
    if (!m_session->isConnected()) {
        m_error = tr("not connected to a rotator");
        return false;
    }
    m_plan = plan;
    if (m_plan.isValid() && m_plan.path.size() != pass.size())
        m_plan.refusal = tr("the plan is not of this pass");
    if (!m_plan.isValid()) {
        m_error = m_plan.refusal;
        return false;
    }
    m_pass = pass;
    m_reach = reach;
    m_aosJulian = aosJulian;
    m_now = std::move(now);
    m_prepositioned = false;
    m_heldForPosition = false;
    m_lastSent.reset();
    m_lastCommand.reset();
    m_figures = TrackingFigures{};
    m_sumSquares = 0;
    m_timer.followClockOf(m_session->link());
    m_timer.setSingleShot(false);
    m_timer.start(m_settings.tickMs);
    setState(State::Waiting, m_plan.describe());
    tick();
    return true;
}

void Tracker::stopTracking(const QString &why)
{
    m_timer.stop();
    if (m_state == State::Waiting || m_state == State::Tracking)
        setState(State::Idle, why);
}

void Tracker::setState(State state, const QString &why)
{
    m_state = state;
    emit stateChanged(state, why);
}

double Tracker::secondsFromAos() const
{
    return m_now ? (m_now() - m_aosJulian) * sky::kSecondsPerDay : 0.0;
}

PathPoint Tracker::pathAt(double seconds) const
{
    const QList<PathPoint> &path = m_plan.path;
    if (seconds <= path.front().seconds)
        return path.front();
    if (seconds >= path.back().seconds)
        return path.back();
    const auto next = std::upper_bound(path.begin(), path.end(), seconds,
                                       [](double s, const PathPoint &p) { return s < p.seconds; });
    const PathPoint &b = *next, &a = *(next - 1);
    const double f = (seconds - a.seconds) / (b.seconds - a.seconds);
    PathPoint p = a;
    p.seconds = seconds;
    // An unwind is a jump: the rotator is sent to its far side, not between.
    if (std::abs(b.azimuth - a.azimuth) < 180.0)
        p.azimuth = a.azimuth + f * (b.azimuth - a.azimuth);
    p.elevation = a.elevation + f * (b.elevation - a.elevation);
    return p;
}

SkyPoint Tracker::skyAt(double seconds) const
{
    if (seconds <= m_pass.front().seconds)
        return m_pass.front();
    if (seconds >= m_pass.back().seconds)
        return m_pass.back();
    const auto next = std::upper_bound(m_pass.begin(), m_pass.end(), seconds,
                                       [](double s, const SkyPoint &p) { return s < p.seconds; });
    const SkyPoint &b = *next, &a = *(next - 1);
    const double f = (seconds - a.seconds) / (b.seconds - a.seconds);
    double turn = std::fmod(b.azimuthDeg - a.azimuthDeg + 540.0, 360.0) - 180.0; // the short way
    double az = std::fmod(a.azimuthDeg + f * turn + 360.0, 360.0);
    return SkyPoint{seconds, az, a.elevationDeg + f * (b.elevationDeg - a.elevationDeg)};
}

SkyPoint Tracker::targetNow() const
{
    return m_pass.isEmpty() ? SkyPoint{} : skyAt(secondsFromAos());
}

void Tracker::sleepUntilDue(double stationSeconds)
{
    // Hours before a pass there is nothing to do but look again: the timer
    // wakes at a twentieth of the time left (the station clock may run up to
    // StationClock::kMaxRate times the rotator's), at most every 30 s, and
    // ticks at its own pace again in the last seconds. A station waiting
    // for its next pass keeps quiet (README: a station at rest).
    const double waitMs = stationSeconds / StationClock::kMaxRate * 1000.0;
    const int interval = int(std::clamp(waitMs, double(m_settings.tickMs), kLongestWaitMs));
    if (m_timer.interval() != interval || !m_timer.isActive())
        m_timer.start(interval);
}

double Tracker::commandFor(double azimuth) const
{
    const model::RotatorLimits &limits = m_reach.limits;
    if (!m_session->hasPosition() || limits.azMax - limits.azMin <= 360.0)
        return azimuth;
    // The same bearing a turn away, where the travel has it.
    std::optional<double> twin;
    for (const double other : {azimuth + 360.0, azimuth - 360.0})
        if (other >= limits.azMin && other <= limits.azMax)
            twin = other;
    const double here = m_session->azimuth();
    if (!twin || std::abs(here - azimuth) <= std::abs(here - *twin))
        return azimuth;
    // A controller that takes a bearing to the nearer of its two angles
    // (the Micro-2g program does, and so does the simulator) would go to the
    // twin: first an angle on the way that only one position has, until the
    // antenna is nearer the one planned.
    const double low = limits.azMax - 360.0, high = limits.azMin + 360.0;
    return std::clamp(azimuth, low + 1.0, high - 1.0);
}

bool Tracker::send(double az, double el, bool duringPass)
{
    // No position read on this link yet (just connected, or back after a
    // blip): nothing is sent blind, and the next tick tries again.
    if (m_session->awaitingPosition()) {
        if (!std::exchange(m_heldForPosition, true))
            emit heldForPosition(m_session->positionNotRead());
        return false;
    }
    m_heldForPosition = false;
    const double command = commandFor(az);
    // The same waypoint already on its way: nothing new to say.
    if (command != az && m_lastCommand && m_lastCommand->first == command && m_lastCommand->second == el)
        return true;
    m_sending = true;
    const session::CommandResult sent = m_session->gotoUnwrapped(command, el);
    m_sending = false;
    if (!sent) {
        // Never pushed on blindly: the planned point should always pass the
        // gate, so a refusal means the limits changed under the plan.
        stopTracking(tr("the rotator refused the planned point: %1").arg(sent.refusal));
        return false;
    }
    m_lastSent = std::pair{az, el};
    m_lastCommand = std::pair{command, el};
    if (duringPass)
        ++m_figures.commands;
    return true;
}

void Tracker::lookAgain()
{
    tick(); // does nothing unless waiting or tracking
}

void Tracker::tick()
{
    if (m_state != State::Waiting && m_state != State::Tracking)
        return;
    const double t = secondsFromAos();
    const double end = m_plan.path.back().seconds;
    if (m_state == State::Waiting) {
        const PathPoint &aos = m_plan.path.front();
        if (!m_prepositioned) {
            // From the measured speeds: how long the move to the AOS point takes.
            double needed = m_settings.arriveEarlySeconds;
            if (m_session->hasPosition()) {
                needed += std::max(std::abs(aos.azimuth - m_session->azimuth()) / m_reach.azimuthRateDegS,
                                   std::abs(aos.elevation - m_session->elevation()) / m_reach.elevationRateDegS);
            } else {
                needed += 360.0 / m_reach.azimuthRateDegS;
            }
            if (t < -needed) {
                sleepUntilDue(-needed - t);
                return;
            }
            if (m_timer.interval() != m_settings.tickMs)
                m_timer.start(m_settings.tickMs);
            if (!send(aos.azimuth, aos.elevation, false))
                return;
            m_prepositioned = true;
            // Started too late to be there on time: say so, with by how much.
            const double travel = needed - m_settings.arriveEarlySeconds;
            if (t <= -travel)
                setState(State::Waiting, tr("moving to the AOS point"));
            else
                setState(State::Waiting, tr("the AOS point is %1 s away at this rotator's speed and AOS is in %2 s: "
                                            "tracking starts late")
                                             .arg(travel, 0, 'f', 0)
                                             .arg(std::max(0.0, -t), 0, 'f', 0));
        } else if (onWaypoint() && !send(aos.azimuth, aos.elevation, false)) {
            return; // on the way to the AOS point by a waypoint: the point itself once it is the nearer
        }
        if (t < 0)
            return;
        setState(State::Tracking, tr("AOS"));
    }
    if (t > end) {
        m_timer.stop();
        m_figures.passSeconds = end - m_plan.path.front().seconds;
        if (m_settings.afterPass == TrackerSettings::AfterPass::Park) {
            m_sending = true;
            m_session->park();
            m_sending = false;
        }
        setState(State::Done, tr("LOS"));
        return;
    }
    // Lead by the response delay, and by half a minimum step more: between
    // two commands the target then swings from half a step behind the
    // antenna to half a step ahead, not from nothing to a whole step behind.
    const PathPoint now = pathAt(std::min(t + m_settings.leadSeconds, end));
    const PathPoint soon = pathAt(std::min(t + m_settings.leadSeconds + 1.0, end));
    // An unwind in between is a jump, not a speed: it must not move where
    // the lead lands, or the commands would flip back and forth across it.
    const double azimuthRate = std::abs(soon.azimuth - now.azimuth) > 180.0 ? 0.0 : std::abs(soon.azimuth - now.azimuth);
    const double rate = std::max(azimuthRate, std::abs(soon.elevation - now.elevation));
    const double halfStep = rate > 1e-6 ? std::min(0.5 * m_settings.minimumStepDeg / rate, 10.0) : 0.0;
    const PathPoint want = pathAt(std::min(t + m_settings.leadSeconds + halfStep, end));
    const bool moved = !m_lastSent || std::abs(want.azimuth - m_lastSent->first) > m_settings.minimumStepDeg
                       || std::abs(want.elevation - m_lastSent->second) > m_settings.minimumStepDeg
                       || onWaypoint();
    if (moved)
        send(want.azimuth, want.elevation, true);
}

void Tracker::onPosition(double az, double el, bool stale)
{
    if (m_state != State::Tracking || stale)
        return;
    const double t = secondsFromAos();
    const SkyPoint target = skyAt(t);
    const double error = skyAngleDeg(az, el, target.azimuthDeg, target.elevationDeg);
    emit pointingError(error, t);
    if (t < kSettleSeconds)
        return;
    ++m_figures.samples;
    m_sumSquares += error * error;
    m_figures.rmsDeg = std::sqrt(m_sumSquares / m_figures.samples);
    m_figures.worstDeg = std::max(m_figures.worstDeg, error);
}

} // namespace slew::tracking
