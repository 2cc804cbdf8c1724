// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The sun and the moon as the site sees them: apparent topocentric
// azimuth and elevation (aberration, nutation and, for the moon, parallax),
// computed with libnova (Meeus's "Astronomical Algorithms"). Times are UTC
// Julian dates; the difference to dynamical time is applied here.

#include "observation.h"
#include "skyvector.h"
#include "site.h"

namespace slew::sky {

enum class SkyBody { Sun, Moon };

struct BodyPosition {
    double azimuthDeg = 0;   // from true north, clockwise
    double elevationDeg = 0; // geometric (no refraction)
    double distanceKm = 0;   // from the earth's centre
    double rightAscensionDeg = 0; // apparent geocentric, of date
    double declinationDeg = 0;
};

BodyPosition bodyPosition(SkyBody body, const Site &site, double julianDate);

// bodyPosition in two halves. The first is the slow one (the moon's theory
// costs 1.7 ms): where the body is seen from the earth's centre, of date.
// It changes slowly enough that a straight line between places ten minutes
// apart is off by under a ten-thousandth of a degree, so a long pass can
// compute it every ten minutes and the fast second half at every point.
struct GeocentricPlace {
    double rightAscensionDeg = 0;
    double declinationDeg = 0;
    double distanceKm = 0;
};
GeocentricPlace geocentricPlace(SkyBody body, double julianDate);
BodyPosition bodyPositionFrom(const GeocentricPlace &place, const Site &site, double julianDate);
inline BodyPosition sunPosition(const Site &s, double jd) { return bodyPosition(SkyBody::Sun, s, jd); }
inline BodyPosition moonPosition(const Site &s, double jd) { return bodyPosition(SkyBody::Moon, s, jd); }

// A fixed point of the sky (a radio source, a star) given by its J2000
// right ascension and declination, as the site sees it now: precession,
// nutation and aberration applied; at infinity, so no parallax. The
// distance is 0.
BodyPosition celestialPosition(double rightAscensionJ2000Deg, double declinationJ2000Deg, const Site &site,
                               double julianDate);

// Geocentric direction to the sun in the equatorial frame of date (close
// enough to TEME for the shadow test), in km.
Vec3 sunVectorEquatorial(double julianDate);

} // namespace slew::sky
