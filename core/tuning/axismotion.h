// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How fast an axis turns, how fast it gets up to speed and how long it takes
// to answer a command, read off a recorded step (stepresponse.h). The
// tracker needs all three (RotatorProfile::motion): the speed to plan a pass
// and to pre-position in time, the acceleration for the start of every long
// move, and the response delay as its lead. The tuning step measures them
// on the rotator itself, so the setup wizard records them with the gains.

#include "stepresponse.h"

#include <QMetaType>
#include <QString>

namespace slew::tuning {

struct AxisMotion {
    double speedDegS = 0;        // the fastest rate held over kSpeedWindowS
    double accelDegS2 = 0;       // from the first movement to 90 % of that speed
    double responseDelayS = 0;   // from the command to the first movement
    bool ok = false;
    QString error;               // why not, when not ok
};

// The span the speed is averaged over: long enough that encoder noise and
// the poll's jitter do not pass for speed.
inline constexpr double kSpeedWindowS = 0.5;
// How long the axis must keep that speed for it to count as its full speed.
inline constexpr double kSpeedHeldS = 1.5;
// A step long enough to measure a G-5500's elevation (2.7°/s) with.
inline constexpr double kMotionStepDeg = 30.0;

// `band`: how far from the start counts as moving (the settling band).
AxisMotion measureAxisMotion(const StepResponse &step, double band);

} // namespace slew::tuning

Q_DECLARE_METATYPE(slew::tuning::AxisMotion)
