// SPDX-License-Identifier: GPL-3.0-or-later
#include "motionguard.h"

#include <QObject>

#include <algorithm>
#include <cmath>

namespace slew::session {

namespace {

// Come back this far from the worst it went the wrong way: it turned back.
constexpr double kTurnedBackDeg = 0.2;

// Degrees between two angles as bearings: 0° and 360° are one.
double bearingApart(double a, double b)
{
    const double turn = std::fmod(std::abs(a - b), 360.0);
    return std::min(turn, 360.0 - turn);
}

} // namespace

void AxisMotionGuard::drive(double nowS, double position, std::optional<double> target, int direction, double arrivedDeg)
{
    const bool wasDriven = m_driven;
    m_restsAt.reset();
    m_target = target;
    m_jogWay = direction > 0 ? 1 : direction < 0 ? -1 : 0;
    m_arrivedDeg = arrivedDeg;
    m_driven = m_settings.enabled && std::isfinite(position) && (!target || std::abs(*target - position) > arrivedDeg);
    if (!m_driven)
        return;
    // Driven on the same way as before: the time since the last progress
    // goes on (a jammed axis under a tracker's stream of targets).
    if (const int way = wayAt(position); !wasDriven || way != m_way)
        restart(nowS, position, way);
}

void AxisMotionGuard::driveByController(double nowS, double position, double restsAt, double arrivedDeg)
{
    m_target.reset();
    m_jogWay = 0;
    m_arrivedDeg = arrivedDeg;
    m_driven = m_settings.enabled && std::isfinite(position) && bearingApart(position, restsAt) > arrivedDeg;
    if (!m_driven)
        return;
    m_restsAt = restsAt;
    restart(nowS, position, 0);
}

int AxisMotionGuard::wayAt(double position) const
{
    if (m_restsAt)
        return 0;
    if (m_target)
        return *m_target >= position ? 1 : -1;
    return m_jogWay;
}

void AxisMotionGuard::restart(double nowS, double position, int way)
{
    m_way = way;
    m_progressFrom = position;
    m_progressSince = nowS;
    m_furthest = position * way;
    m_backSince.reset();
}

std::optional<MotionFault> AxisMotionGuard::reading(double nowS, double position)
{
    if (!m_driven || !std::isfinite(position))
        return std::nullopt;
    if ((m_target && std::abs(*m_target - position) <= m_arrivedDeg)
        || (m_restsAt && bearingApart(position, *m_restsAt) <= m_arrivedDeg)) {
        m_driven = false; // arrived
        return std::nullopt;
    }
    if (const int way = wayAt(position); way != m_way) {
        restart(nowS, position, way); // past its target: the loop turns back
        return std::nullopt;
    }
    // Driven by the controller to where it rests (its own park, either way
    // round): any way is progress, and no way is the wrong one.
    if (m_way == 0) {
        if (std::abs(position - m_progressFrom) >= m_settings.leastProgressDeg) {
            m_progressFrom = position;
            m_progressSince = nowS;
        }
        return noMotion(nowS, position);
    }
    if ((position - m_progressFrom) * m_way >= m_settings.leastProgressDeg) {
        m_progressFrom = position;
        m_progressSince = nowS;
    }
    m_furthest = std::max(m_furthest, position * m_way);
    MotionFault fault;
    fault.at = position;
    fault.towards = m_target;
    fault.direction = m_way;
    const double along = position * m_way;
    if (m_furthest - along > m_settings.runawayDeg) {
        // A drive turned round coasts the old way before it comes back (a
        // fast axis a few degrees): that turns back, a runaway does not.
        if (!m_backSince || along > m_worst + kTurnedBackDeg) {
            m_backSince = nowS; // back for the first time, or turning back
            m_worst = along;
        } else {
            m_worst = std::min(m_worst, along);
        }
        if (nowS - *m_backSince >= m_settings.runawaySeconds) {
            fault.kind = MotionFault::Kind::Runaway;
            fault.seconds = nowS - *m_backSince;
            m_driven = false;
            return fault;
        }
    } else {
        m_backSince.reset();
    }
    return noMotion(nowS, position);
}

std::optional<MotionFault> AxisMotionGuard::noMotion(double nowS, double position)
{
    if ((m_target && std::abs(*m_target - position) <= m_settings.deadbandDeg)
        || (m_restsAt && bearingApart(position, *m_restsAt) <= m_settings.deadbandDeg)) {
        m_progressSince = nowS; // resting where a controller may stop short, or not start
        return std::nullopt;
    }
    if (nowS - m_progressSince < m_settings.noMotionSeconds)
        return std::nullopt;
    MotionFault fault;
    fault.kind = MotionFault::Kind::NoMotion;
    fault.seconds = nowS - m_progressSince;
    fault.at = position;
    fault.towards = m_target;
    fault.direction = m_way;
    m_driven = false;
    return fault;
}

QString describeMotionFault(bool azimuth, const MotionFault &f)
{
    const QString axis = azimuth ? QObject::tr("Azimuth") : QObject::tr("Elevation");
    QString how;
    if (f.towards)
        how = QObject::tr("towards %1°").arg(*f.towards, 0, 'f', 1);
    else if (f.direction == 0)
        how = QObject::tr("by the controller");
    else if (azimuth)
        how = f.direction > 0 ? QObject::tr("clockwise") : QObject::tr("counter-clockwise");
    else
        how = f.direction > 0 ? QObject::tr("up") : QObject::tr("down");
    const QString text = f.kind == MotionFault::Kind::NoMotion
                             ? QObject::tr("%1 did not move for %2 s while driven %3, at %4°: stopped")
                             : QObject::tr("%1 ran the wrong way for %2 s while driven %3, now at %4°: stopped");
    return text.arg(axis).arg(f.seconds, 0, 'f', 1).arg(how).arg(f.at, 0, 'f', 1);
}

} // namespace slew::session
