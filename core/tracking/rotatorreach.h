// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the planner and the tracker know of the session's rotator, taken
// from its profile: the travel as the session's gate has it (in the pointing
// frame, the calibration offsets applied, so a plan and the gate agree on
// every position), the axis speeds and accelerations, the response delay
// (the tracker's lead) and the drive (its minimum step).

#include "passplanner.h"
#include "tracker.h"

#include "model/rotatorprofile.h"

namespace slew::session {
class RotatorSession;
}

namespace slew::tracking {

RotatorReach reachOf(const session::RotatorSession &session);
// The same from a travel and a motion, as a profile gives them (a rotator
// not connected: `slew --schedule`, the benchmarks).
RotatorReach reachOf(const model::RotatorLimits &limits, const model::RotatorMotion &motion);

// The lead and the minimum step for this motion; the rest as `base` has it.
// The lead is the response delay and the time one minimum step takes.
TrackerSettings trackerSettingsFor(const model::RotatorMotion &motion, TrackerSettings base = {});

// How long an axis of this speed and acceleration takes to move `step` degrees.
double stepSeconds(double step, double speed, double accel);

} // namespace slew::tracking
