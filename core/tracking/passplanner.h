// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The pass planner: before AOS, one path for the whole pass that this
// rotator can drive, so that the antenna never goes the long way round.
//
// A pass is a list of sky points (bearing and elevation against time). The
// rotator is its travel (a 0–360° or 0–450° azimuth, a north or a south
// stop, a 0–90° or 0–180° elevation) and how fast each axis turns. The
// planner tries every way of following the pass:
//
//  - the azimuth unwrapped into one continuous run, placed where it fits
//    the travel (a pass over north on a 450° rotator uses the overlap);
//  - on a 0–180° elevation rotator, the flip: azimuth + 180°, elevation
//    180° − el, which moves a north crossing to the south;
//  - on such a rotator, for a pass that climbs high, over the top: the
//    antenna keeps to one vertical plane and the elevation axis carries it
//    through the zenith, so a pass near the zenith needs no fast azimuth
//    swing at all, only a lean as small as the pass misses the zenith by;
//  - only when none fits, a path with a 360° unwind, placed where it
//    costs least;
//
// where the azimuth cannot keep up with the swing near the zenith, takes
// the swing the least-worst way (leastworstswing.h) or shares the lag before
// and after it, whichever predicts better;
//
// then drives each one in its head at the rotator's full rate from the AOS
// point and measures the pointing error as an angle on the sky. The path
// with the smallest worst error wins, then the one with fewer unwinds, then
// the plain way over the flip and the flip over going over the top. Where
// even the best cannot keep up (on a 0–90° elevation axis, a pass near the
// zenith swings the azimuth faster than any rotator of the class can turn),
// the plan says so before AOS: when, for how long, and how far
// behind it will be.
//
// A pure function: the same pass and rotator give the same plan.

#include "model/rotatorlimits.h"

#include <QList>
#include <QString>

#include <optional>

namespace slew::tracking {

// Where the target is at one moment of the pass.
struct SkyPoint {
    double seconds = 0;      // from any fixed moment, increasing
    double azimuthDeg = 0;   // bearing, 0..360 from true north
    double elevationDeg = 0; // above the horizon
};

// What the planner needs to know of the rotator.
struct RotatorReach {
    model::RotatorLimits limits;
    double azimuthRateDegS = 6.0; // the fastest each axis turns
    double elevationRateDegS = 6.0;
    // How fast each axis gets up to speed and brakes; 0: at once. A G-5500
    // takes half a second to reach full speed, which costs a degree and a
    // half of lag at the start of every long move.
    double azimuthAccelDegS2 = 0;
    double elevationAccelDegS2 = 0;
};

// One point of the path: the positions to command, in the rotator's own
// terms (an azimuth may be past 360° or below 0°; an elevation past 90° is
// the flip), and the error predicted there when following at full rate.
struct PathPoint {
    double seconds = 0;
    double azimuth = 0;
    double elevation = 0;
    double predictedErrorDeg = 0;
};

// A stretch where the antenna is predicted to be behind the target by more
// than the planner's threshold.
struct LagSpan {
    double fromSeconds = 0;
    double toSeconds = 0;
    double worstDeg = 0;
};

struct PassPlan {
    bool flipped = false;     // elevation past 90°: azimuth + 180°, 180° − el
    bool overTheTop = false;  // from one horizon through the zenith to the other (flipped after the top)
    bool usesOverlap = false; // some azimuth more than a turn from the azimuth stop
    int unwinds = 0;          // 360° turns back mid-pass: only when nothing avoids one
    QList<PathPoint> path;    // a point per sky point
    QList<LagSpan> lags;      // where the error is predicted over the threshold
    double predictedWorstDeg = 0;
    double predictedRmsDeg = 0;
    QString refusal;          // why there is no plan (an empty pass, an elevation out of reach)

    bool isValid() const { return refusal.isEmpty() && !path.isEmpty(); }
    bool followable() const { return isValid() && lags.isEmpty(); }
    // "flip, no unwind: follows the whole pass (worst 0.12°)"
    QString describe() const;
};

struct PlannerOptions {
    double lagThresholdDeg = 1.0;
    // Where the antenna is now: between equally good paths, the one whose
    // AOS point is nearest.
    std::optional<double> startAzimuth;
};

PassPlan planPass(const QList<SkyPoint> &pass, const RotatorReach &reach, const PlannerOptions &options = {});

// The angle between two pointing directions, each an azimuth and an
// elevation (past 90° pointing back over the top), in degrees.
double skyAngleDeg(double az1, double el1, double az2, double el2);

} // namespace slew::tracking
