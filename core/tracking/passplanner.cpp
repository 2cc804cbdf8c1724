// SPDX-License-Identifier: GPL-3.0-or-later
#include "passplanner.h"

#include "leastworstswing.h"

#include <QObject>
#include <QStringList>

#include <algorithm>
#include <array>
#include <cmath>

namespace slew::tracking {
namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kEpsilon = 1e-9;
// Paths whose worst errors differ by less than this are equally good: the
// next criteria (unwinds, the plain way, the nearest start) decide.
constexpr double kSameErrorDeg = 0.05;
// Below this culmination, crossing over the top swings the elevation axis
// through twice the zenith distance at the crossing, far slower than any
// azimuth swing it would save: such passes are not worth planning that way.
constexpr double kOverTheTopFromDeg = 60.0;

double wrap360(double degrees)
{
    const double d = std::fmod(degrees, 360.0);
    return d < 0 ? d + 360.0 : d;
}

// The signed turn from a to b the short way, in (-180, 180].
double shortTurn(double from, double to)
{
    double d = std::fmod(to - from, 360.0);
    if (d <= -180.0)
        d += 360.0;
    else if (d > 180.0)
        d -= 360.0;
    return d;
}

bool inside(double value, double low, double high)
{
    return value >= low - kEpsilon && value <= high + kEpsilon;
}

struct Candidate {
    PassPlan plan;
    double travel = 0; // degrees of azimuth from the start to AOS and along the path
};

// The pass as this way of pointing sees it: bearings unwrapped into one
// continuous run, and the elevations to command.
struct Run {
    bool flipped = false;
    bool overTheTop = false;
    QList<double> azimuth;   // continuous, starting in 0..360
    QList<double> elevation; // as commanded, before clamping to the travel
};

Run makeRun(const QList<SkyPoint> &pass, bool flipped)
{
    Run run;
    run.flipped = flipped;
    double previous = 0;
    for (int i = 0; i < pass.size(); ++i) {
        const double bearing = wrap360(pass[i].azimuthDeg + (flipped ? 180.0 : 0.0));
        const double az = i == 0 ? bearing : previous + shortTurn(previous, bearing);
        run.azimuth.append(az);
        run.elevation.append(flipped ? 180.0 - pass[i].elevationDeg : pass[i].elevationDeg);
        previous = az;
    }
    return run;
}

// Over the top: the antenna keeps near the vertical plane through `plane`
// (a bearing) and its opposite, and the elevation axis carries it from one
// horizon through the zenith to the other. Each point is taken the way that
// lies within a quarter turn of the plane: as it is on the near side, and
// flipped (bearing + 180°, 180° − el) on the far side. For a pass near the
// zenith this is what a 0–180° elevation axis is for: the sky's bearing
// swings half a turn around the top in seconds, but the plane only has to
// lean a little towards the satellite, by as much as the pass misses the
// zenith. The sharp lean at the top that would follow it exactly is left
// to the rate limit (shareTheLag), which keeps the azimuth near the plane.
Run makeOverTheTopRun(const QList<SkyPoint> &pass, double plane)
{
    Run run;
    run.flipped = run.overTheTop = true;
    for (const SkyPoint &p : pass) {
        const double turn = shortTurn(plane, p.azimuthDeg);
        const bool nearSide = std::abs(turn) <= 90.0;
        run.azimuth.append(wrap360(plane) + (nearSide ? turn : shortTurn(plane, p.azimuthDeg + 180.0)));
        run.elevation.append(nearSide ? p.elevationDeg : 180.0 - p.elevationDeg);
    }
    return run;
}

std::array<double, 3> unitVector(double az, double el)
{
    const double ca = std::cos(az * kDeg), sa = std::sin(az * kDeg);
    const double ce = std::cos(el * kDeg), se = std::sin(el * kDeg);
    return {ce * sa, ce * ca, se}; // east, north, up
}

// The angle between two directions given as vectors of any length.
double angleBetweenDeg(const std::array<double, 3> &a, const std::array<double, 3> &b)
{
    // atan2 of |a×b| and a·b stays accurate for tiny angles, where acos does not.
    const double cx = a[1] * b[2] - a[2] * b[1], cy = a[2] * b[0] - a[0] * b[2], cz = a[0] * b[1] - a[1] * b[0];
    const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), dot) / kDeg;
}

// One axis of the rotator as the planner imagines it: it heads for the
// target at up to `rate`, speeding up and braking at `accel` (0: at once)
// so that it stops on the target rather than past it.
struct AxisFollower {
    double position = 0, velocity = 0;
    double rate = 1, accel = 0;

    void step(double target, double dt)
    {
        const double distance = target - position;
        if (accel <= 0) {
            const double move = std::clamp(distance, -rate * dt, rate * dt);
            position += move;
            velocity = dt > 0 ? move / dt : 0;
            return;
        }
        // The speed from which it can still stop at the target.
        const double stoppable = std::sqrt(2.0 * accel * std::abs(distance));
        const double wanted = std::copysign(std::min(rate, stoppable), distance);
        velocity += std::clamp(wanted - velocity, -accel * dt, accel * dt);
        position += velocity * dt;
    }

    // Stopped (or all but) on `target`.
    bool atRestOn(double target) const { return std::abs(velocity) < 0.05 && std::abs(position - target) < 0.01; }
};

// Drives the path at the rotator's full rate from its first point and
// fills in the predicted error, the lags and the figures.
void predict(const QList<SkyPoint> &pass, const RotatorReach &reach, double threshold, PassPlan &plan)
{
    constexpr double kSubStep = 0.05; // seconds: fine enough for the acceleration
    constexpr double kCreepDeg = 0.1;
    AxisFollower az{plan.path.front().azimuth, 0, reach.azimuthRateDegS, reach.azimuthAccelDegS2};
    AxisFollower el{plan.path.front().elevation, 0, reach.elevationRateDegS, reach.elevationAccelDegS2};
    double sumSquares = 0;
    plan.predictedWorstDeg = 0;
    plan.lags.clear();
    bool lagging = false;
    for (int i = 0; i < plan.path.size(); ++i) {
        PathPoint &p = plan.path[i];
        // The worst between two points counts too: a reading can come at any moment.
        double worstHere = 0;
        // A target that creeps (the sun, the moon, a radio source: hundredths
        // of a degree between points) is followed exactly by an axis at rest
        // on the last point: it covers that in a fraction of a second.
        // Stepping hours of such a pass at kSubStep would take seconds of
        // the window's time for nothing.
        const bool creeping = i > 0 && az.atRestOn(plan.path[i - 1].azimuth) && el.atRestOn(plan.path[i - 1].elevation)
                              && std::abs(p.azimuth - plan.path[i - 1].azimuth) <= kCreepDeg
                              && std::abs(p.elevation - plan.path[i - 1].elevation) <= kCreepDeg;
        if (creeping) {
            az.position = p.azimuth;
            el.position = p.elevation;
            az.velocity = el.velocity = 0;
        } else if (i > 0) {
            const double dt = p.seconds - plan.path[i - 1].seconds;
            const int steps = std::max(1, int(std::ceil(dt / kSubStep)));
            // Between two points the target moves along the sky's shortest
            // arc, not straight across bearing and elevation, which near the
            // zenith (the bearing swinging half a turn in a second) would
            // put it far off its track.
            const auto from = unitVector(pass[i - 1].azimuthDeg, pass[i - 1].elevationDeg);
            const auto to = unitVector(pass[i].azimuthDeg, pass[i].elevationDeg);
            for (int s = 1; s <= steps; ++s) {
                az.step(p.azimuth, dt / steps);
                el.step(p.elevation, dt / steps);
                const double f = double(s) / steps;
                const std::array<double, 3> between{from[0] + f * (to[0] - from[0]), from[1] + f * (to[1] - from[1]),
                                                    from[2] + f * (to[2] - from[2])};
                worstHere = std::max(worstHere, angleBetweenDeg(unitVector(az.position, el.position), between));
            }
        }
        p.predictedErrorDeg = skyAngleDeg(az.position, el.position, pass[i].azimuthDeg, pass[i].elevationDeg);
        worstHere = std::max(worstHere, p.predictedErrorDeg);
        sumSquares += worstHere * worstHere; // the RMS of each second's worst: on the safe side
        plan.predictedWorstDeg = std::max(plan.predictedWorstDeg, worstHere);
        const bool over = worstHere > threshold;
        if (over && !lagging)
            plan.lags.append(LagSpan{p.seconds, p.seconds, 0});
        if (over) {
            plan.lags.back().toSeconds = p.seconds;
            plan.lags.back().worstDeg = std::max(plan.lags.back().worstDeg, worstHere);
        }
        lagging = over;
    }
    plan.predictedRmsDeg = std::sqrt(sumSquares / plan.path.size());
}

// Where the sky asks for more speed than the axis has (the azimuth swing
// near the zenith), a path that only chases falls behind and is worst just
// after the swing. Averaging a forward and a backward rate-limited copy of
// the path gives one that is still within the rate (a mean of two such
// paths is) and starts the swing early by as much as it ends late: the
// error is shared before and after, and its worst about halved. Where the
// axis keeps up, both copies are the path itself and nothing changes.
// Points [from, to) of the path; an unwind is left a jump, done at full
// speed, rather than spread over minutes.
void shareTheLag(QList<PathPoint> &path, int from, int to, double PathPoint::*axis, double rate)
{
    if (to - from < 2)
        return;
    const int n = to - from;
    QList<double> forward(n), backward(n);
    forward.front() = path[from].*axis;
    for (int i = 1; i < n; ++i) {
        const double step = rate * (path[from + i].seconds - path[from + i - 1].seconds);
        forward[i] = forward[i - 1] + std::clamp(path[from + i].*axis - forward[i - 1], -step, step);
    }
    backward.back() = path[to - 1].*axis;
    for (int i = n - 2; i >= 0; --i) {
        const double step = rate * (path[from + i + 1].seconds - path[from + i].seconds);
        backward[i] = backward[i + 1] + std::clamp(path[from + i].*axis - backward[i + 1], -step, step);
    }
    for (int i = 0; i < n; ++i)
        path[from + i].*axis = 0.5 * (forward[i] + backward[i]);
}

// The figures that follow from a path: its unwinds and, driving it in the
// planner's head, its errors and lags.
void finish(const QList<SkyPoint> &pass, const RotatorReach &reach, const PlannerOptions &options, PassPlan &plan)
{
    // Unwinds: whole turns the path travels beyond what the sky does. A
    // change of turn where the sky itself swings half a turn (through the
    // zenith) only picks the other way round, and is none.
    double pathTravel = 0, skyTravel = 0;
    for (int i = 1; i < plan.path.size(); ++i) {
        pathTravel += std::abs(plan.path[i].azimuth - plan.path[i - 1].azimuth);
        skyTravel += std::abs(shortTurn(pass[i - 1].azimuthDeg, pass[i].azimuthDeg));
    }
    plan.unwinds = std::max(0, int(std::floor((pathTravel - skyTravel + 180.0) / 360.0)));
    predict(pass, reach, options.lagThresholdDeg, plan);
}

// The swing taken the least-worst way (leastworstswing.h) on points
// [from, to): the azimuth within the rate, and the elevation that goes with
// it, the way (plain or flipped) each point of the run is taken.
void takeLeastWorstSwing(const QList<SkyPoint> &pass, const Run &run, const QList<double> &centre, int from, int to,
                         const RotatorReach &reach, QList<PathPoint> &path)
{
    const model::RotatorLimits &l = reach.limits;
    QList<SwingPoint> points;
    for (int i = from; i < to; ++i)
        points.append(SwingPoint{pass[i].seconds, centre[i], pass[i].elevationDeg});
    // At the full rate, unlike sharing the lag: the search is exact for an
    // axis that turns at once, and the prediction, which drives the path
    // with the rotator's acceleration, decides whether it wins. On the bench
    // (README, "Tracking") 95 % of the rate cost a pass 2.9° from the zenith
    // 0.11° more at its worst.
    const LeastWorstSwing swing = leastWorstSwing(points, reach.azimuthRateDegS, l.azMin, l.azMax);
    if (swing.azimuth.size() != points.size())
        return;
    for (int i = from; i < to; ++i) {
        const double azimuth = swing.azimuth[i - from];
        const double elevation = elevationOnPlane(pass[i].elevationDeg, azimuth - centre[i]);
        path[i].azimuth = azimuth;
        path[i].elevation = std::clamp(run.elevation[i] > 90.0 ? 180.0 - elevation : elevation, l.elMin, l.elMax);
    }
}

// One path along `run`, starting `turns` whole turns from its first
// azimuth; when the run leaves the travel, it unwinds to the turn that
// brings it back inside, nearest the one it had.
Candidate placeRun(const QList<SkyPoint> &pass, const Run &run, int turns, const RotatorReach &reach,
                   const PlannerOptions &options)
{
    const model::RotatorLimits &l = reach.limits;
    Candidate c;
    c.plan.flipped = run.flipped;
    c.plan.overTheTop = run.overTheTop;
    int k = turns;
    QList<int> turnChanges; // where the path unwinds
    QList<double> centre;   // the run's azimuth in the turn it is placed in
    for (int i = 0; i < run.azimuth.size(); ++i) {
        if (!inside(run.azimuth[i] + 360.0 * k, l.azMin, l.azMax)) {
            // The nearest turn that fits (there is one: the travel spans 360°).
            int best = k;
            for (int d = 1; d <= 3 && best == k; ++d) {
                for (int candidate : {k - d, k + d}) {
                    if (inside(run.azimuth[i] + 360.0 * candidate, l.azMin, l.azMax)) {
                        best = candidate;
                        break;
                    }
                }
            }
            if (best != k)
                turnChanges.append(i);
            k = best;
        }
        centre.append(run.azimuth[i] + 360.0 * k);
        PathPoint p;
        p.seconds = pass[i].seconds;
        p.azimuth = std::clamp(centre.back(), l.azMin, l.azMax);
        p.elevation = std::clamp(run.elevation[i], l.elMin, l.elMax);
        // Past the first turn from the stop: bearings the rotator also
        // reaches the other way round.
        if (p.azimuth > l.azMin + 360.0 + kEpsilon)
            c.plan.usesOverlap = true;
        if (i > 0)
            c.travel += std::abs(p.azimuth - c.plan.path.back().azimuth);
        c.plan.path.append(p);
    }
    if (options.startAzimuth)
        c.travel += std::abs(c.plan.path.front().azimuth - *options.startAzimuth);

    // Where the azimuth cannot keep up, two ways to take the swing: share
    // the lag before and after it, or keep its worst least. Each is driven
    // in the planner's head and the better kept. A little under full rate:
    // the rotator also has to get up to speed.
    const QList<PathPoint> exact = c.plan.path;
    Candidate swung = c;
    bool behind = false;
    int from = 0;
    for (int to : turnChanges + QList<int>{int(c.plan.path.size())}) {
        shareTheLag(c.plan.path, from, to, &PathPoint::azimuth, 0.95 * reach.azimuthRateDegS);
        shareTheLag(c.plan.path, from, to, &PathPoint::elevation, 0.95 * reach.elevationRateDegS);
        for (int i = from; i < to; ++i)
            behind = behind || std::abs(c.plan.path[i].azimuth - exact[i].azimuth) > kEpsilon;
        from = to;
    }
    finish(pass, reach, options, c.plan);
    if (!behind)
        return c;
    from = 0;
    for (int to : turnChanges + QList<int>{int(swung.plan.path.size())}) {
        takeLeastWorstSwing(pass, run, centre, from, to, reach, swung.plan.path);
        shareTheLag(swung.plan.path, from, to, &PathPoint::elevation, 0.95 * reach.elevationRateDegS);
        from = to;
    }
    finish(pass, reach, options, swung.plan);
    const double gain = c.plan.predictedWorstDeg - swung.plan.predictedWorstDeg;
    const bool swingWins =
        gain >= kSameErrorDeg || (gain > -kSameErrorDeg && swung.plan.predictedRmsDeg < c.plan.predictedRmsDeg);
    return swingWins ? swung : c;
}

// Whether a is the better of two paths (see the header).
bool better(const Candidate &a, const Candidate &b)
{
    if (std::abs(a.plan.predictedWorstDeg - b.plan.predictedWorstDeg) >= kSameErrorDeg)
        return a.plan.predictedWorstDeg < b.plan.predictedWorstDeg;
    if (a.plan.unwinds != b.plan.unwinds)
        return a.plan.unwinds < b.plan.unwinds;
    if (a.plan.flipped != b.plan.flipped)
        return !a.plan.flipped;
    if (a.plan.overTheTop != b.plan.overTheTop)
        return !a.plan.overTheTop;
    if (std::abs(a.travel - b.travel) > kEpsilon)
        return a.travel < b.travel;
    return a.plan.predictedRmsDeg < b.plan.predictedRmsDeg;
}

} // namespace

double skyAngleDeg(double az1, double el1, double az2, double el2)
{
    return angleBetweenDeg(unitVector(az1, el1), unitVector(az2, el2));
}

PassPlan planPass(const QList<SkyPoint> &pass, const RotatorReach &reach, const PlannerOptions &options)
{
    PassPlan refused;
    if (pass.isEmpty()) {
        refused.refusal = QObject::tr("the pass has no points");
        return refused;
    }
    const model::RotatorLimits &l = reach.limits;
    if (const QString why = l.validate(); !why.isEmpty()) {
        refused.refusal = why;
        return refused;
    }
    if (l.azMax - l.azMin < 360.0 - kEpsilon) {
        refused.refusal = QObject::tr("the azimuth travel (%1° to %2°) does not reach every bearing").arg(l.azMin).arg(l.azMax);
        return refused;
    }
    if (!(reach.azimuthRateDegS > 0) || !(reach.elevationRateDegS > 0)) {
        refused.refusal = QObject::tr("the rotator's turning rates must be above zero");
        return refused;
    }

    // The ways of pointing: plain; on an elevation axis that goes past the
    // zenith, flipped all along; and, for a pass that climbs high enough to
    // need it, over the top.
    QList<Run> runs{makeRun(pass, false)};
    if (l.elMax > 90.0 + kEpsilon) {
        runs.append(makeRun(pass, true));
        const auto top = std::max_element(pass.begin(), pass.end(), [](const SkyPoint &a, const SkyPoint &b) {
            return a.elevationDeg < b.elevationDeg;
        });
        if (top->elevationDeg >= kOverTheTopFromDeg) {
            // The vertical plane nearest the pass: a high pass rises and
            // sets almost opposite, so halfway between the AOS bearing and
            // the LOS bearing's opposite (not from the top, whose bearing
            // means little at the zenith). Starting on either side of it.
            const double plane = pass.front().azimuthDeg
                                 + 0.5 * shortTurn(pass.front().azimuthDeg, pass.back().azimuthDeg + 180.0);
            runs.append(makeOverTheTopRun(pass, plane));
            runs.append(makeOverTheTopRun(pass, plane + 180.0));
        }
    }
    std::optional<Candidate> best;
    for (const Run &run : runs) {
        // Every whole turn that puts the first point inside the travel: those
        // that fit the whole run have no unwind; the others unwind where forced.
        const int first = int(std::ceil((l.azMin - run.azimuth.front() - kEpsilon) / 360.0));
        const int last = int(std::floor((l.azMax - run.azimuth.front() + kEpsilon) / 360.0));
        for (int turns = first; turns <= last; ++turns) {
            Candidate c = placeRun(pass, run, turns, reach, options);
            if (!best || better(c, *best))
                best = std::move(c);
        }
    }
    return best->plan;
}

QString PassPlan::describe() const
{
    if (!isValid())
        return QObject::tr("no plan: %1").arg(refusal);
    QStringList how;
    how << (overTheTop ? QObject::tr("over the top (elevation through 90°)")
            : flipped  ? QObject::tr("flip (elevation past 90°)")
                       : QObject::tr("plain"));
    if (usesOverlap)
        how << QObject::tr("overlap");
    how << (unwinds == 0 ? QObject::tr("no unwind") : QObject::tr("%n unwind(s)", nullptr, unwinds));
    if (lags.isEmpty())
        return QObject::tr("%1: follows the whole pass (worst %2°)").arg(how.join(QStringLiteral(", ")))
            .arg(predictedWorstDeg, 0, 'f', 2);
    QStringList where;
    for (const LagSpan &s : lags)
        where << QObject::tr("%1 s from +%2 s, up to %3°")
                     .arg(s.toSeconds - s.fromSeconds, 0, 'f', 0)
                     .arg(s.fromSeconds - path.front().seconds, 0, 'f', 0)
                     .arg(s.worstDeg, 0, 'f', 1);
    return QObject::tr("%1: lags behind for %2").arg(how.join(QStringLiteral(", ")), where.join(QStringLiteral("; ")));
}

} // namespace slew::tracking
