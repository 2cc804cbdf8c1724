// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the Station in this process means to do, as the values a face shows:
// the plan of the pass ahead (face/stationplan.h) and the schedule
// (face/stationschedule.h). The window's face (localstationface.h) and
// what the station publishes on a broker (planpublisher.h) read them here.

#include "face/stationplan.h"
#include "face/stationschedule.h"

namespace slew::station {

class Station;

// The pass waited for or followed; no target when there is none.
face::StationPlan planNow(const Station &station);
// The schedule, with every pass's sky points and plan (what a broker is sent
// leaves them out); not running when there is none.
face::StationSchedule scheduleNow(const Station &station);

} // namespace slew::station
