// SPDX-License-Identifier: GPL-3.0-or-later
#include "skytrack.h"

#include <cmath>

namespace slew::tracking {

QList<SkyPoint> sampleSatellitePass(const sky::Sgp4 &satellite, const sky::Station &station, const sky::Pass &pass,
                                    double stepSeconds)
{
    QList<SkyPoint> points;
    const double duration = pass.durationSeconds();
    if (!(stepSeconds > 0) || !(duration >= 0))
        return points;
    const int steps = int(std::ceil(duration / stepSeconds));
    for (int i = 0; i <= steps; ++i) {
        const double seconds = std::min(i * stepSeconds, duration);
        sky::LookAngles look;
        if (!sky::observeSatellite(satellite, station, pass.aos.julian + seconds / sky::kSecondsPerDay, &look))
            continue;
        points.append(SkyPoint{seconds, look.azimuthDeg, look.elevationDeg});
    }
    return points;
}

QList<SkyPoint> sampleBodyPass(sky::SkyBody body, const sky::Station &station, double fromJulian, double toJulian,
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
    if (!(stepSeconds > 0) || !(duration >= 0))
        return points;
    const int steps = int(std::ceil(duration / stepSeconds));
    for (int i = 0; i <= steps; ++i) {
        const double seconds = std::min(i * stepSeconds, duration);
        const sky::BodyPosition p = position(fromJulian + seconds / sky::kSecondsPerDay);
        points.append(SkyPoint{seconds, p.azimuthDeg, p.elevationDeg});
    }
    return points;
}

} // namespace slew::tracking
