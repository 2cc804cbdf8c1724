// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The azimuth swing near the zenith, taken so that the worst pointing error
// is as small as the axis's rate allows.
//
// Near the zenith a pass's bearing swings faster than the azimuth axis can
// turn, so some error is unavoidable. How much an azimuth offset costs
// depends on how high the target is: the antenna, its elevation free, can
// come as close to the target as the vertical plane at its own azimuth
// does, which is asin(|sin h| · cos el) for an offset h. High up, a large
// offset costs little; and once the target is within E of the zenith, the
// antenna can wait at the zenith itself, where its azimuth costs nothing.
//
// So a worst error E allows, at each point, a band of azimuths around the
// target's. Whether one path at the axis's rate fits every band is found by
// carrying the set of azimuths reachable so far forward through the bands;
// the least such E is found by bisection. The path is then drawn backward
// through the reachable sets, at each point as near the target's azimuth as
// the next point allows, so that away from the swing it follows the target
// exactly and the swing starts early by just as much as it must.
//
// The elevation to go with each azimuth is the target's, projected onto the
// vertical plane the antenna is in (the zenith where that plane is a quarter
// turn or more away). The elevation's own rate is left to the planner.

#include "passplanner.h"

#include <QList>

namespace slew::tracking {

struct SwingPoint {
    double seconds = 0;
    double azimuth = 0;      // where the run points, continuous, in the travel's turn
    double skyElevation = 0; // the target's true elevation (0..90)
};

struct LeastWorstSwing {
    QList<double> azimuth; // one per point, within the travel and the rate
    double worstDeg = 0;   // the least worst error of the model (no acceleration, points only)
};

// `rate` in degrees per second; the path stays within [azMin, azMax].
// Empty when the points are not in time order.
LeastWorstSwing leastWorstSwing(const QList<SwingPoint> &points, double rate, double azMin, double azMax);

// The pass as one continuous run of bearings, with no travel to fit.
QList<SwingPoint> unwrappedSwing(const QList<SkyPoint> &pass);

// The floor of a pass for an azimuth axis of `rate`: the least worst error
// any path that turns with the sky can keep, wherever its travel ends and
// with no acceleration. Over the top (passplanner.h) has its own floor, the
// pass's miss of the zenith.
double leastWorstFloorDeg(const QList<SkyPoint> &pass, double rate);

// The elevation (0..90) nearest a target at `skyElevation` for an antenna
// whose azimuth is `offset` degrees from the target's.
double elevationOnPlane(double skyElevation, double offset);

} // namespace slew::tracking
