// SPDX-License-Identifier: GPL-3.0-or-later
#include "sunmoon.h"

#include <libnova/dynamical_time.h>
#include <libnova/earth.h>
#include <libnova/lunar.h>
#include <libnova/parallax.h>
#include <libnova/sidereal_time.h>
#include <libnova/solar.h>
#include <libnova/transform.h>

#include <cmath>

namespace slew::sky {
namespace {

constexpr double kAstronomicalUnitKm = 149597870.7;

// libnova's theories take dynamical time (TT); clocks give UTC.
double dynamicalJulian(double julianDateUtc)
{
    return julianDateUtc + ln_get_dynamical_time_diff(julianDateUtc) / kSecondsPerDay;
}

struct Geocentric {
    ln_equ_posn equatorial{};
    double distanceKm = 0;
};

Geocentric geocentric(SkyBody body, double julianDateUtc)
{
    const double jde = dynamicalJulian(julianDateUtc);
    Geocentric g;
    if (body == SkyBody::Sun) {
        ln_get_solar_equ_coords(jde, &g.equatorial);
        g.distanceKm = ln_get_earth_solar_dist(jde) * kAstronomicalUnitKm;
    } else {
        ln_get_lunar_equ_coords(jde, &g.equatorial);
        g.distanceKm = ln_get_lunar_earth_dist(jde);
    }
    return g;
}

} // namespace

BodyPosition bodyPosition(SkyBody body, const Station &station, double julianDate)
{
    const Geocentric g = geocentric(body, julianDate);
    ln_lnlat_posn observer{station.longitudeDeg, station.latitudeDeg};

    // The moon is 60 earth radii away: seen from the station it is up to a
    // degree from where it is seen from the centre.
    ln_equ_posn shift{};
    ln_equ_posn object = g.equatorial;
    ln_get_parallax(&object, g.distanceKm / kAstronomicalUnitKm, &observer, station.heightM, julianDate, &shift);
    ln_equ_posn topocentric{object.ra + shift.ra, object.dec + shift.dec};

    // Apparent sidereal time, since the positions include nutation.
    ln_hrz_posn horizontal{};
    ln_get_hrz_from_equ_sidereal_time(&topocentric, &observer, ln_get_apparent_sidereal_time(julianDate),
                                      &horizontal);
    BodyPosition p;
    // libnova counts azimuth from the south.
    p.azimuthDeg = wrap360(horizontal.az + 180.0);
    p.elevationDeg = horizontal.alt;
    p.distanceKm = g.distanceKm;
    p.rightAscensionDeg = g.equatorial.ra;
    p.declinationDeg = g.equatorial.dec;
    return p;
}

Vec3 sunVectorEquatorial(double julianDate)
{
    const Geocentric g = geocentric(SkyBody::Sun, julianDate);
    const double ra = radians(g.equatorial.ra), dec = radians(g.equatorial.dec);
    return Vec3{std::cos(dec) * std::cos(ra), std::cos(dec) * std::sin(ra), std::sin(dec)} * g.distanceKm;
}

} // namespace slew::sky
