// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Sun and moon alignment: the operator points the antenna at the sun (or
// the moon) by hand, jogging until the signal peaks or the shadow of the
// feed is centred, and says so. The calibration offsets are then what turns
// the controller's reading into where the body is (RotatorProfile's
// azOffsetDeg and elOffsetDeg).
//
// Where the body is means where it is seen: the apparent position with
// atmospheric refraction, which lifts it by half a degree at the horizon and
// by a tenth at 30°. A reading past 90° of elevation (a flipped antenna)
// points over the top, at the azimuth opposite its own.

#include "sky/site.h"
#include "sky/sunmoon.h"

#include <QString>

namespace slew::tracking {

// Bodies lower than this are refused: refraction there is uncertain by more
// than a beamwidth's share, and trees and roofs are in the way.
inline constexpr double kLowestAlignmentElevationDeg = 5.0;

struct Alignment {
    QString refusal;          // why no offsets were found; empty when they were
    double azOffsetDeg = 0;   // -180..180
    double elOffsetDeg = 0;
    double bodyAzimuthDeg = 0;   // where the body was seen
    double bodyElevationDeg = 0; // apparent, refraction included
    bool ok() const { return refusal.isEmpty(); }
};

// The offsets that make the controller's own reading (readingAz, readingEl:
// the uncalibrated angles) point at `body` at `julian` from `station`.
// An azimuth-only rotator (hasElevation false) gets an azimuth offset only.
Alignment alignOn(sky::SkyBody body, const sky::Site &station, double julian, double readingAz, double readingEl,
                  bool hasElevation = true);

// Standard refraction for a geometric elevation (Saemundsson's formula, as
// given in Meeus's "Astronomical Algorithms"), in degrees; 0 well below the
// horizon.
double refractionDeg(double geometricElevationDeg);

} // namespace slew::tracking
