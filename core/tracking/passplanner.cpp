// SPDX-License-Identifier: GPL-3.0-or-later
#include "passplanner.h"

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

// Drives the path at the rotator's full rate from its first point and
// fills in the predicted error, the lags and the figures.
void predict(const QList<SkyPoint> &pass, const RotatorReach &reach, double threshold, PassPlan &plan)
{
    double az = plan.path.front().azimuth, el = plan.path.front().elevation;
    double sumSquares = 0;
    plan.predictedWorstDeg = 0;
    plan.lags.clear();
    bool lagging = false;
    for (int i = 0; i < plan.path.size(); ++i) {
        PathPoint &p = plan.path[i];
        if (i > 0) {
            const double dt = p.seconds - plan.path[i - 1].seconds;
            const double azStep = reach.azimuthRateDegS * dt, elStep = reach.elevationRateDegS * dt;
            az += std::clamp(p.azimuth - az, -azStep, azStep);
            el += std::clamp(p.elevation - el, -elStep, elStep);
        }
        p.predictedErrorDeg = skyAngleDeg(az, el, pass[i].azimuthDeg, pass[i].elevationDeg);
        sumSquares += p.predictedErrorDeg * p.predictedErrorDeg;
        plan.predictedWorstDeg = std::max(plan.predictedWorstDeg, p.predictedErrorDeg);
        const bool over = p.predictedErrorDeg > threshold;
        if (over && !lagging)
            plan.lags.append(LagSpan{p.seconds, p.seconds, 0});
        if (over) {
            plan.lags.back().toSeconds = p.seconds;
            plan.lags.back().worstDeg = std::max(plan.lags.back().worstDeg, p.predictedErrorDeg);
        }
        lagging = over;
    }
    plan.predictedRmsDeg = std::sqrt(sumSquares / plan.path.size());
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
    int k = turns;
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
                ++c.plan.unwinds;
            k = best;
        }
        PathPoint p;
        p.seconds = pass[i].seconds;
        p.azimuth = std::clamp(run.azimuth[i] + 360.0 * k, l.azMin, l.azMax);
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
    predict(pass, reach, options.lagThresholdDeg, c.plan);
    return c;
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
    if (std::abs(a.travel - b.travel) > kEpsilon)
        return a.travel < b.travel;
    return a.plan.predictedRmsDeg < b.plan.predictedRmsDeg;
}

} // namespace

double skyAngleDeg(double az1, double el1, double az2, double el2)
{
    auto unit = [](double az, double el) {
        const double ca = std::cos(az * kDeg), sa = std::sin(az * kDeg);
        const double ce = std::cos(el * kDeg), se = std::sin(el * kDeg);
        return std::array<double, 3>{ce * sa, ce * ca, se}; // east, north, up
    };
    const auto a = unit(az1, el1), b = unit(az2, el2);
    // atan2 of |a×b| and a·b stays accurate for tiny angles, where acos does not.
    const double cx = a[1] * b[2] - a[2] * b[1], cy = a[2] * b[0] - a[0] * b[2], cz = a[0] * b[1] - a[1] * b[0];
    const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), dot) / kDeg;
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

    std::optional<Candidate> best;
    // The flip needs an elevation axis that goes past the zenith.
    const QList<bool> ways = l.elMax > 90.0 + kEpsilon ? QList<bool>{false, true} : QList<bool>{false};
    for (bool flipped : ways) {
        const Run run = makeRun(pass, flipped);
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
    how << (flipped ? QObject::tr("flip (elevation past 90°)") : QObject::tr("plain"));
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
