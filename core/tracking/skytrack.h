// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A predicted pass as the planner reads it: the target's bearing and
// elevation at even steps from AOS to LOS.

#include "passplanner.h"
#include "sky/passes.h"
#include "sky/sunmoon.h"

#include <functional>

namespace slew::tracking {

// The satellite's look angles every `stepSeconds` from the pass's AOS to
// its LOS (both included); seconds count from AOS. Points the satellite
// cannot be propagated at are left out.
QList<SkyPoint> sampleSatellitePass(const sky::Sgp4 &satellite, const sky::Site &station, const sky::Pass &pass,
                                    double stepSeconds = 1.0);

// The same for the sun or the moon, from `fromJulian` (at or after the
// pass's rise) to its set; seconds count from `fromJulian`.
QList<SkyPoint> sampleBodyPass(sky::SkyBody body, const sky::Site &station, double fromJulian, double toJulian,
                               double stepSeconds = 1.0);

// The same for anything whose position a function gives (tracktarget.h).
QList<SkyPoint> sampleSkyPass(const std::function<sky::BodyPosition(double julian)> &position, double fromJulian,
                              double toJulian, double stepSeconds);

} // namespace slew::tracking
