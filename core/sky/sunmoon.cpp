// SPDX-License-Identifier: GPL-3.0-or-later
#include "sunmoon.h"

#include <libnova/apparent_position.h>
#include <libnova/dynamical_time.h>
#include <libnova/earth.h>
#include <libnova/lunar.h>
#include <libnova/nutation.h>
#include <libnova/parallax.h>
#include <libnova/precession.h>
#include <libnova/sidereal_time.h>
#include <libnova/solar.h>
#include <libnova/transform.h>

#include <cmath>

namespace slew::sky {
namespace {

constexpr double kAstronomicalUnitKm = 149597870.7;

// TT − UTC in seconds. libnova's own table extrapolates badly after 2000
// (134 s for 2024, against 69 s measured), which moves the moon by 0.01°;
// from 1986 to 2150 the polynomials of Espenak & Meeus, "Five Millennium
// Canon of Solar Eclipses" (NASA TP-2006-214141) are used instead.
double deltaTSeconds(double julianDateUtc)
{
    const double year = 2000.0 + (julianDateUtc - kJ2000) / 365.25;
    if (year >= 1986.0 && year < 2005.0) {
        const double t = year - 2000.0;
        return 63.86 + 0.3345 * t - 0.060374 * t * t + 0.0017275 * t * t * t + 0.000651814 * t * t * t * t
               + 0.00002373599 * t * t * t * t * t;
    }
    if (year >= 2005.0 && year < 2050.0) {
        const double t = year - 2000.0;
        return 62.92 + 0.32217 * t + 0.005589 * t * t;
    }
    if (year >= 2050.0 && year < 2150.0) {
        const double u = (year - 1820.0) / 100.0;
        return -20.0 + 32.0 * u * u - 0.5628 * (2150.0 - year);
    }
    return ln_get_dynamical_time_diff(julianDateUtc);
}

// libnova's theories take dynamical time (TT); clocks give UTC.
double dynamicalJulian(double julianDateUtc)
{
    return julianDateUtc + deltaTSeconds(julianDateUtc) / kSecondsPerDay;
}

// Nutation in right ascension and declination (Meeus, "Astronomical
// Algorithms", eq. 23.1).
ln_equ_posn nutated(const ln_equ_posn &p, double jde)
{
    ln_nutation n{};
    ln_get_nutation(jde, &n);
    const double eps = radians(n.ecliptic + n.obliquity);
    const double ra = radians(p.ra), dec = radians(p.dec);
    const double dRa = (std::cos(eps) + std::sin(eps) * std::sin(ra) * std::tan(dec)) * n.longitude
                       - std::cos(ra) * std::tan(dec) * n.obliquity;
    const double dDec = std::sin(eps) * std::cos(ra) * n.longitude + std::sin(ra) * n.obliquity;
    return {wrap360(p.ra + dRa), p.dec + dDec};
}

struct Geocentric {
    ln_equ_posn equatorial{};
    double distanceKm = 0;
};

Geocentric geocentric(SkyBody body, double julianDateUtc)
{
    const double jde = dynamicalJulian(julianDateUtc);
    // Both theories give positions referred to the J2000 equator and
    // equinox; the antenna needs them of date, with nutation, and for the
    // sun with annual aberration (20″; the moon's is below an arcsecond).
    Geocentric g;
    ln_equ_posn j2000{};
    if (body == SkyBody::Sun) {
        ln_get_solar_equ_coords(jde, &j2000);
        ln_equ_posn noProperMotion{0, 0};
        ln_get_apparent_posn(&j2000, &noProperMotion, jde, &g.equatorial);
        g.distanceKm = ln_get_earth_solar_dist(jde) * kAstronomicalUnitKm;
    } else {
        ln_get_lunar_equ_coords(jde, &j2000);
        ln_equ_posn ofDate{};
        ln_get_equ_prec(&j2000, jde, &ofDate);
        g.equatorial = nutated(ofDate, jde);
        g.distanceKm = ln_get_lunar_earth_dist(jde);
    }
    return g;
}

// Where an apparent position of date stands in the site's sky.
BodyPosition horizontalOf(const ln_equ_posn &topocentric, const Site &site, double julianDate)
{
    ln_lnlat_posn observer{site.longitudeDeg, site.latitudeDeg};
    // Apparent sidereal time, since the positions include nutation.
    ln_hrz_posn horizontal{};
    ln_equ_posn object = topocentric;
    ln_get_hrz_from_equ_sidereal_time(&object, &observer, ln_get_apparent_sidereal_time(julianDate), &horizontal);
    BodyPosition p;
    // libnova counts azimuth from the south.
    p.azimuthDeg = wrap360(horizontal.az + 180.0);
    p.elevationDeg = horizontal.alt;
    return p;
}

} // namespace

GeocentricPlace geocentricPlace(SkyBody body, double julianDate)
{
    const Geocentric g = geocentric(body, julianDate);
    return {g.equatorial.ra, g.equatorial.dec, g.distanceKm};
}

BodyPosition bodyPositionFrom(const GeocentricPlace &place, const Site &site, double julianDate)
{
    ln_lnlat_posn observer{site.longitudeDeg, site.latitudeDeg};
    // The moon is 60 earth radii away: seen from the site it is up to a
    // degree from where it is seen from the centre.
    ln_equ_posn shift{};
    ln_equ_posn object{place.rightAscensionDeg, place.declinationDeg};
    ln_get_parallax(&object, place.distanceKm / kAstronomicalUnitKm, &observer, site.heightM, julianDate, &shift);
    BodyPosition p = horizontalOf({object.ra + shift.ra, object.dec + shift.dec}, site, julianDate);
    p.distanceKm = place.distanceKm;
    p.rightAscensionDeg = place.rightAscensionDeg;
    p.declinationDeg = place.declinationDeg;
    return p;
}

BodyPosition bodyPosition(SkyBody body, const Site &site, double julianDate)
{
    return bodyPositionFrom(geocentricPlace(body, julianDate), site, julianDate);
}

BodyPosition celestialPosition(double raJ2000Deg, double decJ2000Deg, const Site &site, double julianDate)
{
    ln_equ_posn j2000{wrap360(raJ2000Deg), decJ2000Deg};
    ln_equ_posn noProperMotion{0, 0};
    ln_equ_posn ofDate{};
    ln_get_apparent_posn(&j2000, &noProperMotion, dynamicalJulian(julianDate), &ofDate);
    BodyPosition p = horizontalOf(ofDate, site, julianDate);
    p.rightAscensionDeg = ofDate.ra;
    p.declinationDeg = ofDate.dec;
    return p;
}

Vec3 sunVectorEquatorial(double julianDate)
{
    const Geocentric g = geocentric(SkyBody::Sun, julianDate);
    const double ra = radians(g.equatorial.ra), dec = radians(g.equatorial.dec);
    return Vec3{std::cos(dec) * std::cos(ra), std::cos(dec) * std::sin(ra), std::sin(dec)} * g.distanceKm;
}

} // namespace slew::sky
