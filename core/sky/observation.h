// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// From a satellite's TEME state to what the antenna needs: Earth-fixed
// coordinates (GMST IAU-82, as "Revisiting Spacetrack Report #3" does; UT1
// is taken as UTC and polar motion is ignored, which moves a LEO satellite
// by well under the beamwidth of any amateur antenna), azimuth, elevation,
// range and range-rate from the site, the Doppler factor, refraction, the
// sub-satellite point and whether the satellite is in sunlight.

#include "skyvector.h"
#include "site.h"

namespace slew::sky {

struct Geodetic {
    double latitudeDeg = 0;
    double longitudeDeg = 0; // -180..180, east positive
    double heightKm = 0;
};

struct LookAngles {
    double azimuthDeg = 0;     // 0..360 from true north, clockwise
    double elevationDeg = 0;   // geometric, unless refraction was asked for
    double rangeKm = 0;
    double rangeRateKmS = 0;   // positive when moving away
};

// Earth rotation (IERS), rad/s.
inline constexpr double kEarthRotationRadS = 7.292115e-5;
inline constexpr double kSpeedOfLightKmS = 299792.458;

Vec3 temeToEarthFixed(const Vec3 &teme, double julianDate);
// Velocity seen from the rotating earth.
Vec3 temeVelocityToEarthFixed(const Vec3 &positionTeme, const Vec3 &velocityTeme, double julianDate);

Vec3 siteEarthFixed(const Site &site); // km, WGS-84
Geodetic earthFixedToGeodetic(const Vec3 &ecef);

// The site's position and local east/north/up axes, worked out once for
// the many look angles of a pass search.
struct SiteFrame {
    explicit SiteFrame(const Site &site);
    Vec3 position, east, north, up;
};

// Look angles to an Earth-fixed position and velocity.
LookAngles lookAnglesEarthFixed(const SiteFrame &site, const Vec3 &positionEcef, const Vec3 &velocityEcef);
inline LookAngles lookAnglesEarthFixed(const Site &site, const Vec3 &positionEcef, const Vec3 &velocityEcef)
{
    return lookAnglesEarthFixed(SiteFrame(site), positionEcef, velocityEcef);
}

// A TEME state in the Earth-fixed frame: position and velocity seen from
// the rotating earth, with one sidereal time.
struct EarthFixedState {
    Vec3 position, velocity;
};
EarthFixedState temeStateToEarthFixed(const Vec3 &positionTeme, const Vec3 &velocityTeme, double julianDate);
// Look angles to a TEME state at a Julian date (UTC).
LookAngles lookAngles(const Site &site, const Vec3 &positionTeme, const Vec3 &velocityTeme, double julianDate);

// The factor a transmitted frequency is multiplied by on arrival:
// 1 − range-rate / c (first order; the relativistic term is 1e-10).
inline double dopplerFactor(double rangeRateKmS) { return 1.0 - rangeRateKmS / kSpeedOfLightKmS; }
inline double dopplerShiftHz(double frequencyHz, double rangeRateKmS)
{
    return frequencyHz * (dopplerFactor(rangeRateKmS) - 1.0);
}

// Standard-atmosphere refraction (Sæmundsson's formula, 10 °C, 1010 hPa):
// how much higher a body appears than it is, in degrees. Zero well below
// the horizon, where the formula means nothing.
double refractionDeg(double geometricElevationDeg);

// The point under the satellite.
Geodetic subSatellitePoint(const Vec3 &positionTeme, double julianDate);

// Whether a TEME position is outside the earth's shadow, with the sun in the
// direction sunTeme (a cylindrical shadow: the penumbra is a few seconds).
bool isSunlit(const Vec3 &positionTeme, const Vec3 &sunDirection);

} // namespace slew::sky
