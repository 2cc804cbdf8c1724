// SPDX-License-Identifier: GPL-3.0-or-later
#include "leastworstswing.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace slew::tracking {
namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kUnbounded = std::numeric_limits<double>::infinity();
// Bisection to well under what a rotator can point to.
constexpr int kBisections = 32;

struct Interval {
    double low = 0, high = 0;
    bool empty() const { return low > high; }
};

// How far the antenna's azimuth may be from the target's for an error of at
// most `worst`: unbounded once the zenith itself is that close.
double halfWidth(double worst, double skyElevation)
{
    const double zenithDistance = 90.0 - skyElevation;
    if (worst >= zenithDistance)
        return kUnbounded;
    // worst < zenith distance, so the ratio is below 1.
    return std::asin(std::sin(worst * kDeg) / std::cos(skyElevation * kDeg)) / kDeg;
}

Interval band(const SwingPoint &p, double worst, double azMin, double azMax)
{
    const double h = halfWidth(worst, p.skyElevation);
    return {std::max(azMin, p.azimuth - h), std::min(azMax, p.azimuth + h)};
}

// The azimuths reachable at each point by a path that keeps within `worst`
// everywhere so far; empty when the path cannot.
QList<Interval> reachableSets(const QList<SwingPoint> &points, double worst, double rate, double azMin, double azMax)
{
    QList<Interval> sets;
    sets.reserve(points.size());
    Interval reach = band(points.front(), worst, azMin, azMax);
    if (reach.empty())
        return {};
    sets.append(reach);
    for (int i = 1; i < points.size(); ++i) {
        const double step = rate * (points[i].seconds - points[i - 1].seconds);
        const Interval allowed = band(points[i], worst, azMin, azMax);
        reach = {std::max(reach.low - step, allowed.low), std::min(reach.high + step, allowed.high)};
        if (reach.empty())
            return {};
        sets.append(reach);
    }
    return sets;
}

} // namespace

QList<SwingPoint> unwrappedSwing(const QList<SkyPoint> &pass)
{
    QList<SwingPoint> points;
    points.reserve(pass.size());
    for (const SkyPoint &p : pass) {
        const double az = points.isEmpty() ? p.azimuthDeg
                                           : points.back().azimuth + std::remainder(p.azimuthDeg - points.back().azimuth, 360.0);
        points.append(SwingPoint{p.seconds, az, p.elevationDeg});
    }
    return points;
}

double leastWorstFloorDeg(const QList<SkyPoint> &pass, double rate)
{
    const double unbounded = std::numeric_limits<double>::max();
    return leastWorstSwing(unwrappedSwing(pass), rate, -unbounded, unbounded).worstDeg;
}

double elevationOnPlane(double skyElevation, double offset)
{
    if (skyElevation >= 90.0)
        return 90.0;
    const double c = std::cos(offset * kDeg);
    if (c <= 0) // the plane is a quarter turn or more away: the zenith is nearest
        return 90.0;
    return std::atan(std::tan(skyElevation * kDeg) / c) / kDeg;
}

LeastWorstSwing leastWorstSwing(const QList<SwingPoint> &points, double rate, double azMin, double azMax)
{
    if (points.isEmpty() || !(rate > 0) || azMin > azMax)
        return {};
    for (int i = 1; i < points.size(); ++i) {
        if (!(points[i].seconds >= points[i - 1].seconds))
            return {};
    }
    // At 90° every band is unbounded: always reachable.
    double low = 0, high = 90.0;
    if (!reachableSets(points, low, rate, azMin, azMax).isEmpty())
        high = low;
    for (int i = 0; i < kBisections && high - low > 1e-6; ++i) {
        const double middle = 0.5 * (low + high);
        (reachableSets(points, middle, rate, azMin, azMax).isEmpty() ? low : high) = middle;
    }
    const QList<Interval> sets = reachableSets(points, high, rate, azMin, azMax);

    // Backward through the sets: each point as near the target's azimuth as
    // its set and the next point allow. The next point lies in this set
    // widened by one step, so the window is never empty.
    LeastWorstSwing swing;
    swing.worstDeg = high;
    swing.azimuth.resize(points.size());
    const int last = int(points.size()) - 1;
    swing.azimuth[last] = std::clamp(points[last].azimuth, sets[last].low, sets[last].high);
    for (int i = last - 1; i >= 0; --i) {
        const double step = rate * (points[i + 1].seconds - points[i].seconds);
        const double low = std::max(sets[i].low, swing.azimuth[i + 1] - step);
        const double high = std::min(sets[i].high, swing.azimuth[i + 1] + step);
        swing.azimuth[i] = std::clamp(points[i].azimuth, low, std::max(low, high));
    }
    return swing;
}

} // namespace slew::tracking
