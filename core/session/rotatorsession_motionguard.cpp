// SPDX-License-Identifier: GPL-3.0-or-later
// RotatorSession's motion guard (motionguard.h): each axis Slew drives is
// watched on every reading; one that does not move, or runs the wrong way,
// is stopped at once and held, and every move that would drive it again is
// refused until the operator clears it. Controllers that report stalls
// (GS, GE) are stopped by their own firmware too; this is for the many
// that report nothing.
// The other files of the session: rotatorsession.cpp and its siblings.

#include "rotatorsession.h"

#include "movewatch.h"

#include <algorithm>
#include <cmath>

namespace slew::session {

double RotatorSession::arrivedWithinDeg(size_t axis) const
{
    // Arrived as MoveWatch judges it: within a degree, or within the
    // controller's own tolerance where that is wider (it stops short by design).
    return std::max(MoveWatch::kArrivedDegrees, axis == 0 ? azStopToleranceDeg() : elStopToleranceDeg());
}

void RotatorSession::setMotionGuard(const MotionGuardSettings &settings)
{
    for (AxisMotionGuard &g : m_guards) {
        g.setSettings(settings);
        if (!settings.enabled)
            g.release();
    }
}

void RotatorSession::guardMove(std::optional<double> az, std::optional<double> el)
{
    const double now = double(nowMs()) / 1000.0;
    const std::array<std::optional<double>, 2> targets{az, isAzimuthOnly() ? std::nullopt : el};
    const std::array<double, 2> at{m_az, m_el};
    for (size_t i = 0; i < 2; ++i) {
        if (targets[i])
            m_guards[i].drive(now, at[i], targets[i], 0, arrivedWithinDeg(i));
        else
            m_guards[i].release();
    }
}

void RotatorSession::guardAxis(Axis axis, double target)
{
    if (axis == Axis::Elevation && isAzimuthOnly())
        return;
    const bool az = axis == Axis::Azimuth;
    m_guards[az ? 0 : 1].drive(double(nowMs()) / 1000.0, az ? m_az : m_el, target, 0, arrivedWithinDeg(az ? 0 : 1));
}

void RotatorSession::guardControllersOwnMove()
{
    // Where it parks not known yet: where it comes to rest cannot be told
    // from a stall, so it is not watched.
    if (!parkKnown()) {
        guardMove(std::nullopt, std::nullopt);
        return;
    }
    const double now = double(nowMs()) / 1000.0;
    m_guards[0].driveByController(now, m_az, parkAzimuth(), arrivedWithinDeg(0));
    if (isAzimuthOnly())
        m_guards[1].release();
    else
        m_guards[1].driveByController(now, m_el, parkElevation(), arrivedWithinDeg(1));
}

void RotatorSession::guardJog()
{
    const double now = double(nowMs()) / 1000.0;
    const std::array<double, 2> at{m_az, m_el};
    for (size_t i = 0; i < 2; ++i) {
        if (m_jogSpeed[i] != 0.0)
            m_guards[i].drive(now, at[i], std::nullopt, m_jogSpeed[i] > 0 ? 1 : -1, arrivedWithinDeg(i));
        else
            m_guards[i].release();
    }
}

void RotatorSession::checkMotion()
{
    const double now = double(nowMs()) / 1000.0;
    const std::array<double, 2> at{m_az, m_el};
    for (size_t i = 0; i < 2; ++i) {
        const std::optional<MotionFault> fault = m_guards[i].reading(now, at[i]);
        if (!fault)
            continue;
        const bool azimuth = i == 0;
        m_motionFaults[i] = describeMotionFault(azimuth, *fault);
        // The one axis that misbehaves, unless the dialect stops both at once.
        stop(azimuth ? tr("the motion guard: the azimuth") : tr("the motion guard: the elevation"),
             azimuth ? Axes::Azimuth : Axes::Elevation);
        emit motionFaultChanged(azimuth ? Axis::Azimuth : Axis::Elevation, m_motionFaults[i]);
    }
}

QString RotatorSession::motionHold(std::optional<double> az, std::optional<double> el) const
{
    const std::array<std::optional<double>, 2> to{az, el};
    const std::array<double, 2> at{m_az, m_el};
    for (size_t i = 0; i < 2; ++i) {
        if (m_motionFaults[i].isEmpty() || !to[i])
            continue;
        // A move that leaves the held axis where it is (the other axis' go-to
        // on a dialect that sets both) does not drive it.
        if (std::isfinite(at[i]) && std::abs(*to[i] - at[i]) <= arrivedWithinDeg(i))
            continue;
        return axisHeld(i == 0 ? Axis::Azimuth : Axis::Elevation);
    }
    return {};
}

QString RotatorSession::axisHeld(Axis axis) const
{
    const QString &fault = m_motionFaults[axis == Axis::Azimuth ? 0 : 1];
    if (fault.isEmpty())
        return {};
    return tr("the %1 is held after the motion guard stopped it (%2): clear the fault once it is looked at")
        .arg(axis == Axis::Azimuth ? tr("azimuth") : tr("elevation"), fault);
}

bool RotatorSession::clearMotionFaults(const QString &who)
{
    if (!hasMotionFault())
        return false;
    m_motionFaults = {};
    emit motionFaultsCleared(who);
    return true;
}

} // namespace slew::session
