// SPDX-License-Identifier: GPL-3.0-or-later
#include "joglegs.h"

#include <algorithm>
#include <cmath>

namespace slew::session {

double JogLegs::legEnd(int axis, double speed, const Where &here)
{
    const bool az = axis == 0;
    const double at = az ? here.azimuth : here.elevation;
    if (speed > 0)
        return std::min(az ? here.limits.azMax : here.limits.elMax, at + kLegDeg);
    return std::max(az ? here.limits.azMin : here.limits.elMin, at - kLegDeg);
}

std::optional<std::array<double, 2>> JogLegs::leg(const std::array<double, 2> &speeds, int jogged, const Where &here)
{
    std::array<double, 2> ends{
        speeds[0] != 0.0 ? legEnd(0, speeds[0], here) : here.azimuth,
        speeds[1] != 0.0 ? legEnd(1, speeds[1], here) : here.elevation,
    };
    if (here.fixedElevation)
        ends[1] = *here.fixedElevation;
    const double from = jogged == 0 ? here.azimuth : here.elevation;
    if (std::abs(ends[size_t(jogged)] - from) < kLeastMoveDeg)
        return std::nullopt;
    return ends;
}

std::optional<int> JogLegs::wantsNext(const std::array<double, 2> &speeds, const Where &here) const
{
    for (int i : {0, 1}) {
        if (speeds[size_t(i)] == 0.0 || (i == 1 && here.fixedElevation))
            continue;
        const double at = i == 0 ? here.azimuth : here.elevation;
        const double next = legEnd(i, speeds[size_t(i)], here);
        if (std::abs(m_leg[size_t(i)] - at) < kRenewDeg && std::abs(next - m_leg[size_t(i)]) > kLeastMoveDeg)
            return i;
    }
    return std::nullopt;
}

} // namespace slew::session
