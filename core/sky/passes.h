// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Pass prediction: when a satellite (or the sun, or the moon) is above a
// minimum elevation at the site, and above its horizon mask
// (horizonmask.h) where it has one. A pass has its acquisition (AOS), the
// time of closest approach (TCA, taken as the moment of highest elevation,
// which is what an antenna cares about) and its loss (LOS), each with the
// azimuth, and whether the satellite is in sunlight during it.
//
// The search steps through time, as far as the object provably cannot
// cross the threshold (for a satellite: its angle from the site about
// the earth's centre, against the largest angle at which it can be up and
// the fastest it can move), then pins each crossing down by bisection to
// 10 ms and the peak by golden section. A pass that clears the threshold for
// less than the shortest step (30 s for satellites) can be missed; such
// passes are of no use to a rotator anyway.

#include "sgp4.h"
#include "sgp4propagator.h"
#include "site.h"
#include "sunmoon.h"
#include "elementset.h"

#include <QList>
#include <QString>

#include <atomic>
#include <functional>

namespace slew::sky {

struct PassPoint {
    double julian = 0;
    double azimuthDeg = 0;
    double elevationDeg = 0;
};

struct Pass {
    QString name;
    int catalogueNumber = 0;  // 0 for the sun and the moon
    PassPoint aos, tca, los;
    bool aosClipped = false;  // already up when the window opened
    bool losClipped = false;  // still up when the search gave up
    bool sunlit = false;      // in sunlight for some of the pass
    double maxElevationDeg() const { return tca.elevationDeg; }
    double durationSeconds() const { return (los.julian - aos.julian) * kSecondsPerDay; }
};

struct PassWindow {
    double startJulian = 0;
    double endJulian = 0;        // passes that begin before this are reported whole
    double minElevationDeg = 0;  // where AOS and LOS are: the horizon (0), or another crossing
    // When set and true, the search ends at its next step with what it has
    // found: how a worker thread is told to give up (a service stopping).
    const std::atomic<bool> *stop = nullptr;
    // Only passes whose highest point climbs to this. What a "minimum
    // elevation" means everywhere (slew --passes --min-el, the schedule,
    // --track): a filter of the passes, never a move of their AOS and LOS.
    double leastHighestDeg = -90.0;
};

// The next passes of one satellite. A satellite that cannot be propagated
// (decayed, invalid elements) has none.
QList<Pass> predictPasses(const Sgp4 &satellite, const Site &site, const PassWindow &window);

// Every satellite, all passes sorted by AOS.
QList<Pass> predictPasses(const QList<ElementSet> &satellites, const Site &site, const PassWindow &window);

// Rise, culmination and set of the sun or the moon above the window's
// minimum elevation. The almanac's sunrise and sunset put the centre at
// kRiseSetElevationDeg: the upper limb on the horizon, lifted by standard
// refraction.
inline constexpr double kRiseSetElevationDeg = -0.8333;
QList<Pass> predictBodyPasses(SkyBody body, const Site &site, const PassWindow &window);
// Rise, culmination and set of a fixed point of the sky (sunmoon.h,
// celestialPosition), its centre on the window's minimum elevation.
QList<Pass> predictCelestialPasses(double rightAscensionJ2000Deg, double declinationJ2000Deg, const Site &site,
                                   const PassWindow &window);

// The engine, on any elevation function: exposed for tests. It ends on any
// input: a window or steps that are not finite numbers give no passes, an
// elevation that stops being a finite number ends the search there, and the
// number of steps is bounded by the window's length.
struct ElevationSample {
    double elevationDeg = 0;
    double azimuthDeg = 0;
    // A proven lower bound on the time before the elevation can cross the
    // threshold (from geometry); 0 when the function knows none.
    double quietSeconds = 0;
};
using ElevationFunction = std::function<ElevationSample(double julian)>;
struct PassScan {
    double maxElevationRateDegS = 1.0; // bound on |d elevation / dt|, for the step below the threshold
    double inPassStepS = 30.0;
    double maxStepS = 600.0;
};
// With a horizon mask, a pass is where the elevation is above the mask as
// well as the window's minimum; its points (AOS, TCA, LOS) are then the
// object's own elevations. Behind a mask the scan takes steps of at most
// five minutes: a gap in the mask narrower than that, crossed in less
// time, can be missed (of no use to a rotator either).
QList<Pass> scanPasses(const ElevationFunction &elevation, const PassWindow &window, const PassScan &scan,
                       const HorizonMask *horizon = nullptr);

// The satellite's look angles at a time; false when it cannot be propagated.
bool observeSatellite(const Sgp4 &satellite, const Site &site, double julian, LookAngles *out);
// The same for one of a run of times: the propagator carries what it can to the next.
bool observeSatellite(Sgp4Propagator &satellite, const Site &site, double julian, LookAngles *out);

} // namespace slew::sky
