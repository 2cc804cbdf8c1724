// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A predicted pass as the planner reads it: the target's bearing and
// elevation at even steps from AOS to LOS.

#include "passplanner.h"
#include "sky/passes.h"

namespace slew::tracking {

// The satellite's look angles every `stepSeconds` from the pass's AOS to
// its LOS (both included); seconds count from AOS. Points the satellite
// cannot be propagated at are left out.
QList<SkyPoint> sampleSatellitePass(const sky::Sgp4 &satellite, const sky::Station &station, const sky::Pass &pass,
                                    double stepSeconds = 1.0);

} // namespace slew::tracking
