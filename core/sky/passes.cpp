// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes.h"

#include "observation.h"

#include <algorithm>
#include <cmath>

namespace slew::sky {
namespace {

constexpr double kSecond = 1.0 / kSecondsPerDay;
constexpr double kCrossingTolerance = 0.01 * kSecond;
constexpr double kPeakTolerance = 0.1 * kSecond;
// A pass still going on at the window's end is followed this far at most.
constexpr double kFollowBeyondWindow = 1.0;

// The time in (below, above] where the elevation crosses the threshold,
// given one side below it and the other above.
double bisectCrossing(const ElevationFunction &f, double below, double above, double threshold)
{
    while (std::fabs(above - below) > kCrossingTolerance) {
        const double mid = 0.5 * (below + above);
        if (f(mid).elevationDeg >= threshold)
            above = mid;
        else
            below = mid;
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
    while (b - a > kPeakTolerance) {
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

QList<Pass> scanPasses(const ElevationFunction &f, const PassWindow &window, const PassScan &scan)
{
    QList<Pass> passes;
    const double threshold = window.minElevationDeg;
    const double inPassStep = scan.inPassStepS * kSecond;

    double t = window.startJulian;
    double elevation = f(t).elevationDeg;
    bool inPass = elevation >= threshold;
    Pass current;
    // The highest sample so far in the current pass, to bracket the peak.
    double bestSampleTime = t, bestSampleElevation = elevation;
    if (inPass) {
        current.aos = pointAt(f, t);
        current.aosClipped = true;
    }

    const double hardEnd = window.endJulian + kFollowBeyondWindow;
    while (true) {
        if (!inPass && t >= window.endJulian)
            break;
        if (inPass && t >= hardEnd) {
            current.los = pointAt(f, t);
            current.losClipped = true;
            current.tca = pointAt(f, goldenSectionPeak(f, std::max(current.aos.julian, bestSampleTime - inPassStep),
                                                       std::min(t, bestSampleTime + inPassStep)));
            passes.append(current);
            break;
        }
        double step = inPassStep;
        if (!inPass) {
            // Far below the threshold the object cannot come up quickly.
            const double seconds = (threshold - elevation) / scan.maxElevationRateDegS;
            step = std::clamp(seconds, scan.inPassStepS / 2.0, scan.maxStepS) * kSecond;
        }
        const double next = inPass ? t + step : std::min(t + step, window.endJulian);
        const double nextElevation = f(next).elevationDeg;
        if (!inPass && nextElevation >= threshold) {
            current = Pass();
            current.aos = pointAt(f, bisectCrossing(f, t, next, threshold));
            inPass = true;
            bestSampleTime = next;
            bestSampleElevation = nextElevation;
        } else if (inPass && nextElevation < threshold) {
            // bisectCrossing wants the "above" end second: search from LOS backwards.
            const double los = bisectCrossing(f, next, t, threshold);
            current.los = pointAt(f, los);
            const double from = std::max(current.aos.julian, bestSampleTime - inPassStep);
            const double to = std::min(los, bestSampleTime + inPassStep);
            current.tca = pointAt(f, goldenSectionPeak(f, from, to));
            passes.append(current);
            inPass = false;
        } else if (inPass && nextElevation > bestSampleElevation) {
            bestSampleTime = next;
            bestSampleElevation = nextElevation;
        }
        t = next;
        elevation = nextElevation;
    }
    return passes;
}

bool observeSatellite(const Sgp4 &satellite, const Station &station, double julian, LookAngles *out)
{
    const Sgp4State s = satellite.propagateToJulian(julian);
    if (!s.ok())
        return false;
    *out = lookAngles(station, s.positionKm, s.velocityKmS, julian);
    return true;
}

QList<Pass> predictPasses(const Sgp4 &satellite, const Station &station, const PassWindow &window)
{
    if (satellite.initialError() != Sgp4Error::None)
        return {};
    const ElevationFunction f = [&](double julian) {
        LookAngles look;
        if (!observeSatellite(satellite, station, julian, &look))
            return ElevationSample{-90.0, 0.0};
        return ElevationSample{look.elevationDeg, look.azimuthDeg};
    };
    // How fast the elevation can change below the horizon: the satellite's
    // angular rate about the earth's centre, magnified by up to five times
    // as seen from the ground (the factor is (R + h) / range at the
    // horizon, 4 for a 200 km orbit), plus the earth's own rotation.
    const double orbitRateDegS = satellite.elements().meanMotionRevPerDay * 360.0 / kSecondsPerDay;
    PassScan scan;
    scan.maxElevationRateDegS = 5.0 * orbitRateDegS + degrees(kEarthRotationRadS);

    QList<Pass> passes = scanPasses(f, window, scan);
    for (Pass &p : passes) {
        p.name = satellite.elements().displayName();
        p.catalogueNumber = satellite.elements().catalogueNumber;
        // Sunlit if it is in sunlight at any of a few moments of the pass.
        const int samples = 8;
        for (int i = 0; i <= samples && !p.sunlit; ++i) {
            const double julian = p.aos.julian + (p.los.julian - p.aos.julian) * i / samples;
            const Sgp4State s = satellite.propagateToJulian(julian);
            p.sunlit = s.ok() && isSunlit(s.positionKm, sunVectorEquatorial(julian));
        }
    }
    return passes;
}

QList<Pass> predictPasses(const QList<Tle> &satellites, const Station &station, const PassWindow &window)
{
    QList<Pass> all;
    for (const Tle &tle : satellites)
        all += predictPasses(Sgp4(tle), station, window);
    std::stable_sort(all.begin(), all.end(), [](const Pass &a, const Pass &b) { return a.aos.julian < b.aos.julian; });
    return all;
}

QList<Pass> predictBodyPasses(SkyBody body, const Station &station, const PassWindow &window)
{
    const ElevationFunction f = [&](double julian) {
        const BodyPosition p = bodyPosition(body, station, julian);
        return ElevationSample{p.elevationDeg, p.azimuthDeg};
    };
    PassScan scan;
    // The sky turns 0.0042°/s; nothing rises faster than that.
    scan.maxElevationRateDegS = degrees(kEarthRotationRadS) * 1.05;
    scan.inPassStepS = 600.0;
    scan.maxStepS = 3600.0;
    QList<Pass> passes = scanPasses(f, window, scan);
    for (Pass &p : passes) {
        p.name = body == SkyBody::Sun ? QStringLiteral("Sun") : QStringLiteral("Moon");
        p.sunlit = true;
    }
    return passes;
}

} // namespace slew::sky
