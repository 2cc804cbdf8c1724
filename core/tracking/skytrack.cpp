// SPDX-License-Identifier: GPL-3.0-or-later
#include "skytrack.h"

#include "input/finitenumber.h"

#include <cmath>

namespace slew::tracking {
namespace {

// A pass is followed for at most a day past its window (passes.cpp), and a
// fixed target is held for at most the look-ahead; more samples than this
// would be a time that is not a number, not a pass.
constexpr double kLongestSampledSeconds = 3.0 * 86400.0;

bool sampleable(double durationSeconds, double stepSeconds)
{
    return input::allFinite(durationSeconds, stepSeconds) && stepSeconds > 0 && durationSeconds >= 0
           && durationSeconds <= kLongestSampledSeconds;
}

} // namespace

QList<SkyPoint> sampleSatellitePass(const sky::Sgp4 &satellite, const sky::Site &station, const sky::Pass &pass,
                                    double stepSeconds)
{
    QList<SkyPoint> points;
    const double duration = pass.durationSeconds();
    if (!sampleable(duration, stepSeconds))
        return points;
    const int steps = int(std::ceil(duration / stepSeconds));
    sky::Sgp4Propagator propagator(satellite); // the times go forward: each goes on from the last
    for (int i = 0; i <= steps; ++i) {
        const double seconds = std::min(i * stepSeconds, duration);
        sky::LookAngles look;
        if (!sky::observeSatellite(propagator, station, pass.aos.julian + seconds / sky::kSecondsPerDay, &look))
            continue;
        points.append(SkyPoint{seconds, look.azimuthDeg, look.elevationDeg});
    }
    return points;
}

QList<SkyPoint> sampleBodyPass(sky::SkyBody body, const sky::Site &station, double fromJulian, double toJulian,
                               double stepSeconds)
{
    return sampleSkyPass([&](double julian) { return sky::bodyPosition(body, station, julian); }, fromJulian, toJulian,
                         stepSeconds);
}

QList<SkyPoint> sampleSkyPass(const std::function<sky::BodyPosition(double julian)> &position, double fromJulian,
                              double toJulian, double stepSeconds)
{
    QList<SkyPoint> points;
    const double duration = (toJulian - fromJulian) * sky::kSecondsPerDay;
    if (!sampleable(duration, stepSeconds))
        return points;
    const int steps = int(std::ceil(duration / stepSeconds));
    for (int i = 0; i <= steps; ++i) {
        const double seconds = std::min(i * stepSeconds, duration);
        const sky::BodyPosition p = position(fromJulian + seconds / sky::kSecondsPerDay);
        if (input::allFinite(p.azimuthDeg, p.elevationDeg))
            points.append(SkyPoint{seconds, p.azimuthDeg, p.elevationDeg});
    }
    return points;
}

} // namespace slew::tracking
