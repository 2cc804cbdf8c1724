// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Made-up passes for the tracking tests: the target moves along a great
// circle of the sky at a steady rate, highest at a chosen bearing.

#include "tracking/passplanner.h"

#include <algorithm>
#include <array>
#include <cmath>

// Highest (maxEl) at bearing `culminationAz`, heading towards
// culminationAz + 90° (clockwise) or - 90°, `rateDegS` of arc a second,
// sampled every `stepS` seconds from horizon to horizon.
inline QList<slew::tracking::SkyPoint> greatCirclePass(double culminationAz, double maxEl, bool clockwise,
                                                       double rateDegS = 0.5, double stepS = 1.0)
{
    constexpr double kDeg = M_PI / 180.0;
    auto vec = [](double az, double el) {
        return std::array<double, 3>{std::cos(el * kDeg) * std::sin(az * kDeg), std::cos(el * kDeg) * std::cos(az * kDeg),
                                     std::sin(el * kDeg)};
    };
    const auto top = vec(culminationAz, maxEl);
    const auto along = vec(culminationAz + (clockwise ? 90.0 : -90.0), 0);
    QList<slew::tracking::SkyPoint> points;
    for (double seconds = 0; seconds <= 180.0 / rateDegS + 1e-9; seconds += stepS) {
        const double theta = seconds * rateDegS - 90.0;
        const double c = std::cos(theta * kDeg), s = std::sin(theta * kDeg);
        const double e = c * top[0] + s * along[0], n = c * top[1] + s * along[1], u = c * top[2] + s * along[2];
        const double el = std::asin(std::clamp(u, -1.0, 1.0)) / kDeg;
        if (el < 0)
            continue;
        double az = std::atan2(e, n) / kDeg;
        if (az < 0)
            az += 360.0;
        points.append(slew::tracking::SkyPoint{seconds, az, el});
    }
    return points;
}
