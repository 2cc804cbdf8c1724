// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the pass runner of the station in this process is doing, in the
// words every face uses (face/trackingnow.h).

#include "face/trackingnow.h"

namespace slew::tracking {
class PassRunner;
}

namespace slew::station {

// Read off the pass runner (none: off).
face::TrackingNow trackingNow(const tracking::PassRunner *runner);

} // namespace slew::station
