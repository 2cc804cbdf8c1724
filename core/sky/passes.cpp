// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes.h"

#include "input/finitenumber.h"

#include "observation.h"

#include <algorithm>
#include <cmath>

namespace slew::sky {
namespace {

constexpr double kSecond = 1.0 / kSecondsPerDay;
constexpr double kCrossingTolerance = 0.01 * kSecond;
constexpr double kPeakTolerance = 0.5 * kSecond;
// A pass still going on at the window's end is followed this far at most.
constexpr double kFollowBeyondWindow = 1.0;
// The longest step the scan takes behind a horizon mask (passes.h).
constexpr double kLongestStepBehindMaskS = 300.0;

QList<Pass> scanAboveThreshold(const ElevationFunction &f, const PassWindow &window, const PassScan &scan);
QList<Pass> scanAboveMask(const ElevationFunction &f, const PassWindow &window, const PassScan &scan,
                          const HorizonMask &horizon);

// The time where the elevation crosses the threshold, given one end of the
// bracket below it and the other above; the answer is on the "above" side,
// within the tolerance. Regula falsi with the Illinois modification: the
// elevation is smooth, so this needs a handful of evaluations where
// bisection needs twenty; a bisection step whenever the bracket does not
// halve keeps the worst case bounded.
double bisectCrossing(const ElevationFunction &f, double below, double above, double threshold)
{
    double fBelow = f(below).elevationDeg - threshold;
    double fAbove = f(above).elevationDeg - threshold;
    int side = 0;
    // Each round at least halves the bracket every second round, so a day
    // comes down to 10 ms in well under a hundred; the cap is a guarantee.
    for (int round = 0; round < 200 && std::fabs(above - below) > kCrossingTolerance; ++round) {
        const double width = std::fabs(above - below);
        double t = (fAbove - fBelow) != 0.0 ? above - fAbove * (above - below) / (fAbove - fBelow)
                                            : 0.5 * (above + below);
        // Keep the probe strictly inside, a tolerance from either end, so the
        // bracket always shrinks.
        const double lo = std::min(below, above) + kCrossingTolerance / 2;
        const double hi = std::max(below, above) - kCrossingTolerance / 2;
        t = std::clamp(t, lo, hi);
        const double value = f(t).elevationDeg - threshold;
        if (value >= 0.0) {
            above = t;
            fAbove = value;
            if (side == 1)
                fBelow /= 2.0;
            side = 1;
        } else {
            below = t;
            fBelow = value;
            if (side == -1)
                fAbove /= 2.0;
            side = -1;
        }
        if (std::fabs(above - below) > 0.5 * width) {
            // Slow progress: one bisection step.
            const double mid = 0.5 * (below + above);
            const double v = f(mid).elevationDeg - threshold;
            if (v >= 0.0) {
                above = mid;
                fAbove = v;
            } else {
                below = mid;
                fBelow = v;
            }
            side = 0;
        }
    }
    return above;
}

// The highest point between a and b, for an elevation that rises then falls.
double goldenSectionPeak(const ElevationFunction &f, double a, double b)
{
    const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
    double c = b - ratio * (b - a);
    double d = a + ratio * (b - a);
    double fc = f(c).elevationDeg, fd = f(d).elevationDeg;
    for (int round = 0; round < 200 && b - a > kPeakTolerance; ++round) {
        if (fc > fd) {
            b = d;
            d = c;
            fd = fc;
            c = b - ratio * (b - a);
            fc = f(c).elevationDeg;
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + ratio * (b - a);
            fd = f(d).elevationDeg;
        }
    }
    return 0.5 * (a + b);
}

PassPoint pointAt(const ElevationFunction &f, double julian)
{
    const ElevationSample s = f(julian);
    return {julian, s.azimuthDeg, s.elevationDeg};
}

} // namespace

QList<Pass> scanPasses(const ElevationFunction &f, const PassWindow &window, const PassScan &scan,
                       const HorizonMask *horizon)
{
    QList<Pass> passes = horizon ? scanAboveMask(f, window, scan, *horizon) : scanAboveThreshold(f, window, scan);
    passes.removeIf([&window](const Pass &p) { return p.maxElevationDeg() < window.leastHighestDeg; });
    return passes;
}

namespace {

QList<Pass> scanAboveMask(const ElevationFunction &f, const PassWindow &window, const PassScan &scan,
                          const HorizonMask &horizon)
{
    const double floor = window.minElevationDeg;
    // The one threshold stands for both: the elevation is lowered by as
    // much as the mask rises over the window's minimum at its azimuth.
    const ElevationFunction masked = [&](double julian) {
        ElevationSample s = f(julian);
        // A bound from geometry holds for the minimum, and so for the mask,
        // only while the object is below the minimum: above it, the mask can
        // hide it or show it at any moment.
        if (!(s.elevationDeg < floor))
            s.quietSeconds = 0;
        s.elevationDeg -= std::max(0.0, horizon.elevationAt(s.azimuthDeg) - floor);
        return s;
    };
    PassScan steps = scan;
    steps.maxStepS = std::min(scan.maxStepS, kLongestStepBehindMaskS);
    steps.inPassStepS = std::min(scan.inPassStepS, kLongestStepBehindMaskS);
    QList<Pass> passes = scanAboveThreshold(masked, window, steps);
    for (Pass &p : passes) {
        // The object's own elevations: at AOS, that is the mask's there.
        p.aos = pointAt(f, p.aos.julian);
        p.los = pointAt(f, p.los.julian);
        p.tca = pointAt(f, goldenSectionPeak(f, p.aos.julian, p.los.julian));
    }
    return passes;
}

QList<Pass> scanAboveThreshold(const ElevationFunction &f, const PassWindow &window, const PassScan &scan)
{
    QList<Pass> passes;
    const double threshold = window.minElevationDeg;
    const double minStep = scan.inPassStepS / 2.0;
    // A window or a step that is not a finite number would make the time
    // below NaN, and the loop's end test never true.
    if (!input::allFinite(window.startJulian, window.endJulian, threshold, scan.inPassStepS, scan.maxStepS,
                          scan.maxElevationRateDegS)
        || !(minStep > 0) || !(scan.maxElevationRateDegS > 0) || window.endJulian < window.startJulian)
        return passes;
    // Every step moves on by at least minStep, so this many steps cover the
    // window and the pass followed past its end; the count is a second
    // guarantee that the loop ends, whatever the elevation function does.
    const double hardEnd = window.endJulian + kFollowBeyondWindow;
    const qint64 mostSteps = qint64(std::ceil((hardEnd - window.startJulian) * kSecondsPerDay / minStep)) + 16;
    qint64 steps = 0;

    double t = window.startJulian;
    ElevationSample sample = f(t);
    if (!std::isfinite(sample.elevationDeg))
        return passes;
    bool inPass = sample.elevationDeg >= threshold;
    Pass current;
    // The highest sample of the current pass and the samples either side
    // of it: the peak lies between those two.
    double bestElevation = -1e9, bestLo = t, bestHi = t;
    bool bestHiKnown = false;
    if (inPass) {
        current.aos = pointAt(f, t);
        current.aosClipped = true;
        bestElevation = sample.elevationDeg;
    }
    auto finishPass = [&](double los, bool clipped) {
        current.los = pointAt(f, los);
        current.losClipped = clipped;
        current.tca = pointAt(f, goldenSectionPeak(f, bestLo, bestHiKnown ? bestHi : los));
        passes.append(current);
    };

    while (true) {
        if (!inPass && t >= window.endJulian)
            break;
        if (++steps > mostSteps || (window.stop && window.stop->load(std::memory_order_relaxed))) {
            if (inPass)
                finishPass(t, true);
            break;
        }
        if (inPass && t >= hardEnd) {
            finishPass(t, true);
            break;
        }
        // How far the elevation cannot reach the threshold: by the rate
        // bound, or by the function's own geometry if that says more.
        const double margin = std::fabs(sample.elevationDeg - threshold);
        double seconds = std::max(margin / scan.maxElevationRateDegS, sample.quietSeconds);
        seconds = std::clamp(seconds, inPass ? scan.inPassStepS : minStep, scan.maxStepS);
        const double next = inPass ? t + seconds * kSecond : std::min(t + seconds * kSecond, window.endJulian);
        const ElevationSample nextSample = f(next);
        if (!std::isfinite(nextSample.elevationDeg)) {
            // The object can no longer be computed (a satellite decayed in
            // the model): what was found so far stands.
            if (inPass)
                finishPass(t, true);
            break;
        }
        const bool nextUp = nextSample.elevationDeg >= threshold;
        if (!inPass && nextUp) {
            current = Pass();
            current.aos = pointAt(f, bisectCrossing(f, t, next, threshold));
            inPass = true;
            bestElevation = nextSample.elevationDeg;
            bestLo = current.aos.julian;
            bestHiKnown = false;
        } else if (inPass && !nextUp) {
            // Bisect from the side that is up: the last moment above.
            finishPass(bisectCrossing(f, next, t, threshold), false);
            inPass = false;
        } else if (inPass && nextSample.elevationDeg > bestElevation) {
            bestElevation = nextSample.elevationDeg;
            bestLo = t;
            bestHiKnown = false;
        } else if (inPass && !bestHiKnown) {
            bestHi = next;
            bestHiKnown = true;
        }
        t = next;
        sample = nextSample;
    }
    return passes;
}

} // namespace

bool observeSatellite(const Sgp4 &satellite, const Site &site, double julian, LookAngles *out)
{
    Sgp4Propagator once(satellite);
    return observeSatellite(once, site, julian, out);
}

bool observeSatellite(Sgp4Propagator &satellite, const Site &site, double julian, LookAngles *out)
{
    const Sgp4State s = satellite.propagateToJulian(julian);
    if (!s.ok())
        return false;
    const LookAngles look = lookAngles(site, s.positionKm, s.velocityKmS, julian);
    if (!input::allFinite(look.azimuthDeg, look.elevationDeg, look.rangeKm, look.rangeRateKmS))
        return false;
    *out = look;
    return true;
}

QList<Pass> predictPasses(const Sgp4 &satellite, const Site &site, const PassWindow &window)
{
    if (satellite.initialError() != Sgp4Error::None)
        return {};
    const ElementSet &tle = satellite.elements();

    // Geometry that bounds how soon the satellite can rise or set. Seen
    // from the earth's centre, a satellite at radius r is above elevation E
    // only within the angle ψ(r) = acos(R cos E / r) − E of the site. It
    // moves over the ground no faster than its angular rate at perigee plus
    // the earth's rotation, so while it is further than ψ(apogee) away it
    // cannot rise, and while it is nearer than ψ(perigee) it cannot set.
    // Half a degree covers the difference between the geocentric and the
    // geodetic vertical; 1 % on the radii (60 km for a LEO) covers the
    // short-period terms and a week of drag.
    const SiteFrame frame(site);
    const Vec3 siteEcef = frame.position;
    const double siteRadius = siteEcef.norm();
    const Vec3 siteUnit = siteEcef * (1.0 / siteRadius);
    const double meanMotionRadS = tle.meanMotionRevPerDay * kTwoPi / kSecondsPerDay;
    const double semiMajorKm = std::cbrt(398600.8 / (meanMotionRadS * meanMotionRadS)); // Kepler's third law
    const double e = tle.eccentricity;
    const double apogee = semiMajorKm * (1.0 + e) * 1.01;
    const double perigee = semiMajorKm * (1.0 - e) * 0.99;
    const double threshold = radians(window.minElevationDeg);
    const double margin = radians(0.5);
    auto visibleAngle = [&](double radius) {
        const double c = siteRadius * std::cos(threshold) / radius;
        return c >= 1.0 ? 0.0 : std::acos(c) - threshold;
    };
    const double riseAngle = visibleAngle(apogee) + margin;
    const double setAngle = std::max(0.0, visibleAngle(perigee) - margin);
    const double perigeeRate = meanMotionRadS * (1.0 + e) * (1.0 + e) / std::pow(1.0 - e * e, 1.5);
    const double groundRate = (perigeeRate + kEarthRotationRadS) * 1.05;

    // The scan asks for times mostly in order: a deep-space set's resonance
    // integration goes on from one to the next. This call's own, so the
    // Sgp4 may be scanned on several threads at once.
    Sgp4Propagator propagator(satellite);
    const ElevationFunction f = [&](double julian) {
        const Sgp4State s = propagator.propagateToJulian(julian);
        if (!s.ok())
            return ElevationSample{-90.0, 0.0, 0.0};
        const EarthFixedState fixed = temeStateToEarthFixed(s.positionKm, s.velocityKmS, julian);
        const Vec3 &r = fixed.position;
        const LookAngles look = lookAnglesEarthFixed(frame, r, fixed.velocity);
        const double angle = std::acos(std::clamp(siteUnit.dot(r) / r.norm(), -1.0, 1.0));
        double quiet = 0.0;
        if (look.elevationDeg < window.minElevationDeg)
            quiet = std::max(0.0, (angle - riseAngle) / groundRate);
        else
            quiet = std::max(0.0, (setAngle - angle) / groundRate);
        return ElevationSample{look.elevationDeg, look.azimuthDeg, quiet};
    };
    PassScan scan;
    scan.maxElevationRateDegS = 1e9; // the geometry above is the bound
    scan.inPassStepS = 60.0;
    scan.maxStepS = 3600.0;

    QList<Pass> passes = scanPasses(f, window, scan, site.horizon.get());
    for (Pass &p : passes) {
        p.name = tle.displayName();
        p.catalogueNumber = tle.catalogueNumber;
        // Sunlit if it is in sunlight at any of a few moments of the pass;
        // the sun moves a quarter of a degree in a LEO pass, so one
        // direction serves the whole pass.
        const Vec3 sun = sunVectorEquatorial(p.tca.julian);
        const int samples = 4;
        for (int i = 0; i <= samples && !p.sunlit; ++i) {
            const double julian = p.aos.julian + (p.los.julian - p.aos.julian) * i / samples;
            const Sgp4State s = propagator.propagateToJulian(julian);
            p.sunlit = s.ok() && isSunlit(s.positionKm, sun);
        }
    }
    return passes;
}

QList<Pass> predictPasses(const QList<ElementSet> &satellites, const Site &site, const PassWindow &window)
{
    QList<Pass> all;
    for (const ElementSet &tle : satellites)
        all += predictPasses(Sgp4(tle), site, window);
    std::stable_sort(all.begin(), all.end(), [](const Pass &a, const Pass &b) { return a.aos.julian < b.aos.julian; });
    return all;
}

namespace {

// Anything that turns with the sky: it rises no faster than the sky turns.
QList<Pass> skyPasses(const std::function<BodyPosition(double)> &position, const QString &name,
                      const PassWindow &window, const HorizonMask *horizon)
{
    const ElevationFunction f = [&](double julian) {
        const BodyPosition p = position(julian);
        return ElevationSample{p.elevationDeg, p.azimuthDeg};
    };
    PassScan scan;
    // The sky turns 0.0042°/s; nothing rises faster than that.
    scan.maxElevationRateDegS = degrees(kEarthRotationRadS) * 1.05;
    scan.inPassStepS = 600.0;
    scan.maxStepS = 3600.0;
    QList<Pass> passes = scanPasses(f, window, scan, horizon);
    for (Pass &p : passes) {
        p.name = name;
        p.sunlit = true;
    }
    return passes;
}

} // namespace

QList<Pass> predictBodyPasses(SkyBody body, const Site &site, const PassWindow &window)
{
    return skyPasses([&](double julian) { return bodyPosition(body, site, julian); },
                     body == SkyBody::Sun ? QStringLiteral("Sun") : QStringLiteral("Moon"), window,
                     site.horizon.get());
}

QList<Pass> predictCelestialPasses(double ra, double dec, const Site &site, const PassWindow &window)
{
    return skyPasses([&](double julian) { return celestialPosition(ra, dec, site, julian); },
                     QStringLiteral("RA %1° Dec %2°").arg(ra, 0, 'f', 3).arg(dec, 0, 'f', 3), window,
                     site.horizon.get());
}

} // namespace slew::sky
