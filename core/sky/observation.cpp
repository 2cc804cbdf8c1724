// SPDX-License-Identifier: GPL-3.0-or-later
#include "observation.h"

#include "sgp4.h"

#include <algorithm>
#include <cmath>

namespace slew::sky {
namespace {

// WGS-84, the ellipsoid GPS and the operator's map use.
constexpr double kWgs84RadiusKm = 6378.137;
constexpr double kWgs84Flattening = 1.0 / 298.257223563;
constexpr double kWgs84EccSq = kWgs84Flattening * (2.0 - kWgs84Flattening);

} // namespace

Vec3 temeToEarthFixed(const Vec3 &p, double julianDate)
{
    // TEME and the pseudo Earth-fixed frame differ by a rotation about the
    // pole through GMST.
    const double g = gmstIau82(julianDate);
    const double c = std::cos(g), s = std::sin(g);
    return {c * p.x + s * p.y, -s * p.x + c * p.y, p.z};
}

Vec3 temeVelocityToEarthFixed(const Vec3 &positionTeme, const Vec3 &velocityTeme, double julianDate)
{
    const Vec3 r = temeToEarthFixed(positionTeme, julianDate);
    const Vec3 v = temeToEarthFixed(velocityTeme, julianDate);
    return {v.x + kEarthRotationRadS * r.y, v.y - kEarthRotationRadS * r.x, v.z};
}

Vec3 siteEarthFixed(const Site &site)
{
    const double lat = radians(site.latitudeDeg);
    const double lon = radians(site.longitudeDeg);
    const double h = site.heightM / 1000.0;
    const double sinLat = std::sin(lat);
    const double primeVertical = kWgs84RadiusKm / std::sqrt(1.0 - kWgs84EccSq * sinLat * sinLat);
    return {(primeVertical + h) * std::cos(lat) * std::cos(lon),
            (primeVertical + h) * std::cos(lat) * std::sin(lon),
            (primeVertical * (1.0 - kWgs84EccSq) + h) * sinLat};
}

Geodetic earthFixedToGeodetic(const Vec3 &p)
{
    // Fixed-point iteration on the latitude; converges to below a
    // millimetre in a handful of steps for anything above the earth.
    const double rho = std::hypot(p.x, p.y);
    double lat = std::atan2(p.z, rho * (1.0 - kWgs84EccSq));
    double height = 0;
    for (int i = 0; i < 6; ++i) {
        const double sinLat = std::sin(lat);
        const double primeVertical = kWgs84RadiusKm / std::sqrt(1.0 - kWgs84EccSq * sinLat * sinLat);
        height = rho / std::cos(lat) - primeVertical;
        lat = std::atan2(p.z, rho * (1.0 - kWgs84EccSq * primeVertical / (primeVertical + height)));
    }
    return {degrees(lat), degrees(std::atan2(p.y, p.x)), height};
}

SiteFrame::SiteFrame(const Site &site)
    : position(siteEarthFixed(site))
{
    const double lat = radians(site.latitudeDeg);
    const double lon = radians(site.longitudeDeg);
    const double sinLat = std::sin(lat), cosLat = std::cos(lat);
    const double sinLon = std::sin(lon), cosLon = std::cos(lon);
    east = {-sinLon, cosLon, 0.0};
    north = {-sinLat * cosLon, -sinLat * sinLon, cosLat};
    up = {cosLat * cosLon, cosLat * sinLon, sinLat};
}

LookAngles lookAnglesEarthFixed(const SiteFrame &site, const Vec3 &positionEcef, const Vec3 &velocityEcef)
{
    const Vec3 rho = positionEcef - site.position;
    LookAngles look;
    look.rangeKm = rho.norm();
    look.azimuthDeg = wrap360(degrees(std::atan2(rho.dot(site.east), rho.dot(site.north))));
    look.elevationDeg = degrees(std::asin(std::clamp(rho.dot(site.up) / look.rangeKm, -1.0, 1.0)));
    look.rangeRateKmS = rho.dot(velocityEcef) / look.rangeKm;
    return look;
}

EarthFixedState temeStateToEarthFixed(const Vec3 &p, const Vec3 &v, double julianDate)
{
    const double g = gmstIau82(julianDate);
    const double c = std::cos(g), s = std::sin(g);
    const Vec3 r{c * p.x + s * p.y, -s * p.x + c * p.y, p.z};
    const Vec3 vr{c * v.x + s * v.y, -s * v.x + c * v.y, v.z};
    return {r, {vr.x + kEarthRotationRadS * r.y, vr.y - kEarthRotationRadS * r.x, vr.z}};
}

LookAngles lookAngles(const Site &site, const Vec3 &positionTeme, const Vec3 &velocityTeme, double julianDate)
{
    const EarthFixedState e = temeStateToEarthFixed(positionTeme, velocityTeme, julianDate);
    return lookAnglesEarthFixed(SiteFrame(site), e.position, e.velocity);
}

double refractionDeg(double elevationDeg)
{
    if (elevationDeg < -1.0)
        return 0.0;
    // Sæmundsson (Sky & Telescope, 1986): R in arcminutes from the true altitude.
    const double h = elevationDeg;
    return 1.02 / std::tan(radians(h + 10.3 / (h + 5.11))) / 60.0;
}

Geodetic subSatellitePoint(const Vec3 &positionTeme, double julianDate)
{
    return earthFixedToGeodetic(temeToEarthFixed(positionTeme, julianDate));
}

bool isSunlit(const Vec3 &p, const Vec3 &sunDirection)
{
    const Vec3 sun = sunDirection * (1.0 / sunDirection.norm());
    const double along = p.dot(sun);
    if (along >= 0.0)
        return true;
    const Vec3 across = p - sun * along;
    return across.norm() > kWgs84RadiusKm;
}

} // namespace slew::sky
