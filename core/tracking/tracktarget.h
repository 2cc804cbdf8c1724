// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What Slew can track, and where it is: a satellite from the loaded element
// sets, the sun, the moon, a fixed azimuth and elevation (a drift scan, a
// beacon, a terrestrial link), or a fixed point of the sky given by its
// J2000 right ascension and declination (a radio source).
//
// TargetSky answers the same three questions for every kind, so the station
// service and the window never ask which kind they hold: the passes above a
// minimum elevation, a pass sampled for the planner, and where the target is
// at a moment.

#include "passplanner.h"

#include "sky/passes.h"
#include "sky/sgp4.h"
#include "sky/site.h"
#include "sky/elementsetformat.h"

#include <QList>
#include <QString>

#include <memory>
#include <optional>

namespace slew::tracking {

struct TrackTarget {
    enum class Kind { Satellite, Sun, Moon, Fixed, Celestial };
    Kind kind = Kind::Satellite;
    sky::ElementSet elements;                 // Satellite
    double azimuthDeg = 0;             // Fixed
    double elevationDeg = 0;
    double rightAscensionDeg = 0;      // Celestial, J2000
    double declinationDeg = 0;

    QString name() const;
    // The target stays put on the antenna's sky (Fixed): there is no pass to
    // plan, only a position to hold.
    bool isFixed() const { return kind == Kind::Fixed; }

    // "azel:AZ,EL" (degrees) or "radec:RA,DEC": RA in hours (0..24), or in
    // degrees with a trailing d; Dec in degrees; either may be written
    // sexagesimal, "radec:23:23:24,+58:48:54". Empty when `spec` names
    // neither kind; `error` set when it names one badly.
    static std::optional<TrackTarget> parseFixedOrCelestial(const QString &spec, QString *error);
};

class TargetSky {
public:
    explicit TargetSky(const TrackTarget &target);

    const TrackTarget &target() const { return m_target; }

    // Passes whose AOS falls in the window (one in progress included). A
    // fixed target above the minimum elevation has one pass the length of
    // the window.
    QList<sky::Pass> passes(const sky::Site &station, const sky::PassWindow &window) const;
    // The pass from `fromJulian` (at or after its AOS) to its LOS, as the
    // planner reads it: seconds from `fromJulian`.
    QList<SkyPoint> sample(const sky::Site &station, const sky::Pass &pass, double fromJulian) const;
    // Where the target is at `julian`; a satellite's range and range rate
    // too. Empty when a satellite cannot be propagated. Asked every tick, so
    // a satellite's propagation carries on from the last call: not const,
    // and for one thread at a time (a copy has its own).
    std::optional<sky::LookAngles> lookAt(const sky::Site &station, double julian);

private:
    TrackTarget m_target;
    std::shared_ptr<const sky::Sgp4> m_satellite; // built once: SGP4 set-up is not free
    std::optional<sky::Sgp4Propagator> m_ticking; // lookAt's, on *m_satellite (which every copy shares)
};

} // namespace slew::tracking
