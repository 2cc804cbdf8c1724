// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A jog on a controller with no command to run an axis (Rot2Prog,
// Rot1Prog, Micro-2g): set-position legs towards the end of the
// travel, each renewed before it runs out, for as long as the jog is held.
//
// Safe as a speed command is: every leg ends inside the limits, the
// controller brakes there by itself, and Stop (the release, or any other)
// ends it. The speed is the controller's own. A leg is less than half a
// turn, so a controller that takes a set as a bearing and turns the short
// way to it (360° is north, 0°) still turns the way the operator pressed;
// the next leg follows before this one ends. Pure: the session sends.

#include "model/rotatorlimits.h"

#include <array>
#include <optional>

namespace slew::session {

class JogLegs {
public:
    static constexpr double kLegDeg = 170.0;   // under half a turn: no bearing is ambiguous
    static constexpr double kRenewDeg = 30.0;  // the next leg goes out this far before the end
    static constexpr double kLeastMoveDeg = 1.0; // within a degree of a leg's end, a jog does nothing

    // Where the antenna is, and where it may go.
    struct Where {
        double azimuth = 0.0;
        double elevation = 0.0;
        model::RotatorLimits limits;
        // An azimuth-only rotator's elevation stays at this.
        std::optional<double> fixedElevation;
    };

    // The leg for the axes' speeds (°/s, signed; 0: the axis holds where it
    // is): both axes' ends, for one set. Empty when the axis `jogged` is
    // already at the end of its travel that way.
    static std::optional<std::array<double, 2>> leg(const std::array<double, 2> &speeds, int jogged, const Where &here);

    void started(const std::array<double, 2> &leg) { m_leg = leg; }
    // Called with each position: the axis (0 azimuth, 1 elevation) still
    // jogging whose leg has nearly run out where the travel goes on past
    // it, so the next leg should go; empty while none has.
    std::optional<int> wantsNext(const std::array<double, 2> &speeds, const Where &here) const;

private:
    static double legEnd(int axis, double speed, const Where &here);
    std::array<double, 2> m_leg{0.0, 0.0};
};

} // namespace slew::session
