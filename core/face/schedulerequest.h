// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What an operator asks of a schedule besides its targets: how many hours
// ahead it plans, the least elevation a pass must reach, and the time kept
// free between two passes. The same defaults as the Station's own
// (station/schedulerunner.h's ScheduleOptions), and the same ranges as
// `slew --schedule` takes, so a request is judged alike from every face.

#include "input/finitenumber.h"

namespace slew::face {

struct ScheduleRequest {
    double hours = 24;
    double minElevationDeg = 0;
    double guardSeconds = 30;
};

inline constexpr input::NumberRange kScheduleHours{0.1, 168, " hours"};
inline constexpr input::NumberRange kScheduleMinElevation{-5, 90, "°"};
inline constexpr input::NumberRange kScheduleGuard{0, 3600, " s"};

} // namespace slew::face
