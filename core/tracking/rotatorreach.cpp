// SPDX-License-Identifier: GPL-3.0-or-later
#include "rotatorreach.h"

#include "session/rotatorsession.h"

namespace slew::tracking {

RotatorReach reachOf(const session::RotatorSession &session)
{
    const model::RotatorMotion &m = session.profile().motion;
    RotatorReach r;
    r.limits = session.moveGate().limits();
    r.azimuthRateDegS = m.azSpeedDegS;
    r.elevationRateDegS = m.elSpeedDegS;
    r.azimuthAccelDegS2 = m.azAccelDegS2;
    r.elevationAccelDegS2 = m.elAccelDegS2;
    return r;
}

TrackerSettings trackerSettingsFor(const model::RotatorMotion &motion, TrackerSettings base)
{
    base.leadSeconds = motion.responseDelayS;
    if (motion.trackStepDeg > 0.0)
        base.minimumStepDeg = motion.trackStepDeg;
    else
        base.minimumStepDeg = motion.drive == model::RotatorMotion::Drive::Relay ? kRelayMinimumStepDeg
                                                                               : kServoMinimumStepDeg;
    return base;
}

} // namespace slew::tracking
