// SPDX-License-Identifier: GPL-3.0-or-later
#include "skyalignment.h"

#include <QObject>

#include <cmath>
#include <numbers>

namespace slew::tracking {

namespace {

constexpr double kLargestElevationOffsetDeg = 20.0; // as RotatorProfile allows

double radians(double deg)
{
    return deg * std::numbers::pi / 180.0;
}

// -180..180
double signedAngle(double deg)
{
    const double r = std::remainder(deg, 360.0);
    return r <= -180.0 ? r + 360.0 : r;
}

} // namespace

double refractionDeg(double h)
{
    if (!(h > -1.0))
        return 0.0;
    // Saemundsson: R in arc minutes, for the true (geometric) altitude h.
    const double arcMinutes = 1.02 / std::tan(radians(h + 10.3 / (h + 5.11)));
    return std::max(0.0, arcMinutes / 60.0);
}

Alignment alignOn(sky::SkyBody body, const sky::Site &station, double julian, double readingAz, double readingEl,
                  bool hasElevation)
{
    Alignment a;
    const QString name = body == sky::SkyBody::Sun ? QObject::tr("the sun") : QObject::tr("the moon");
    if (!std::isfinite(readingAz) || !std::isfinite(readingEl)) {
        a.refusal = QObject::tr("the rotator's position is not known yet");
        return a;
    }
    const sky::BodyPosition seen = sky::bodyPosition(body, station, julian);
    a.bodyAzimuthDeg = seen.azimuthDeg;
    a.bodyElevationDeg = seen.elevationDeg + refractionDeg(seen.elevationDeg);
    if (a.bodyElevationDeg < kLowestAlignmentElevationDeg) {
        a.refusal = QObject::tr("%1 is at %2° elevation: too low to align on (%3° or more)")
                        .arg(name)
                        .arg(a.bodyElevationDeg, 0, 'f', 1)
                        .arg(kLowestAlignmentElevationDeg, 0, 'f', 0);
        return a;
    }
    // The direction the boom must have: over the top when the reading is.
    const bool flipped = hasElevation && readingEl > 90.0;
    const double boomAz = flipped ? a.bodyAzimuthDeg + 180.0 : a.bodyAzimuthDeg;
    const double boomEl = flipped ? 180.0 - a.bodyElevationDeg : a.bodyElevationDeg;
    a.azOffsetDeg = signedAngle(boomAz - readingAz);
    a.elOffsetDeg = hasElevation ? boomEl - readingEl : 0.0;
    if (std::abs(a.elOffsetDeg) > kLargestElevationOffsetDeg) {
        a.refusal = QObject::tr("the elevation would be off by %1°, more than %2°: is the antenna on %3?")
                        .arg(a.elOffsetDeg, 0, 'f', 1)
                        .arg(kLargestElevationOffsetDeg, 0, 'f', 0)
                        .arg(name);
        return a;
    }
    return a;
}

} // namespace slew::tracking
