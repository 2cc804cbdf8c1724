// SPDX-License-Identifier: GPL-3.0-or-later
#include "rotatorreach.h"

#include "session/rotatorsession.h"

#include <cmath>

namespace slew::tracking {

RotatorReach reachOf(const session::RotatorSession &session)
{
    return reachOf(session.moveGate().limits(), session.profile().motion);
}

RotatorReach reachOf(const model::RotatorLimits &limits, const model::RotatorMotion &m)
{
    RotatorReach r;
    r.limits = limits;
    r.azimuthRateDegS = m.azSpeedDegS;
    r.elevationRateDegS = m.elSpeedDegS;
    r.azimuthAccelDegS2 = m.azAccelDegS2;
    r.elevationAccelDegS2 = m.elAccelDegS2;
    return r;
}

double stepSeconds(double step, double speed, double accel)
{
    if (!(accel > 0.0))
        return speed > 0.0 ? step / speed : 0.0;
    // Up to speed and down again; a short step never reaches full speed.
    const double peak = std::sqrt(step * accel);
    return peak <= speed ? 2.0 * peak / accel : step / speed + speed / accel;
}

TrackerSettings trackerSettingsFor(const model::RotatorMotion &motion, TrackerSettings base)
{
    if (motion.trackStepDeg > 0.0)
        base.minimumStepDeg = motion.trackStepDeg;
    else
        base.minimumStepDeg = motion.drive == model::RotatorMotion::Drive::Relay ? kRelayMinimumStepDeg
                                                                               : kServoMinimumStepDeg;
    // Commands go out a step at a time, and each step takes the axis a while
    // to make after it answers: both are lag to lead by. For a G-5500
    // (0.1 s, 0.5° at 12°/s²) that is 0.51 s, where bench_tracking found
    // the smallest error (of 0, 0.5, 1 and 1.5 s).
    base.leadSeconds = motion.responseDelayS
                       + stepSeconds(base.minimumStepDeg, motion.azSpeedDegS, motion.azAccelDegS2);
    return base;
}

} // namespace slew::tracking
