// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A station's schedule as a face shows it: whether it runs, the passes
// taken and dropped with the reason, and the one followed. Published on a
// broker as JSON (remote/stationschedule.h).

#include "schedule/schedule.h"

#include <optional>

namespace slew::face {

struct StationSchedule {
    qint64 unixMs = 0;
    qint64 clockMs = 0;     // the station clock then
    double clockRate = 1;   // its seconds a real second
    bool running = false;
    bool planned = false;        // running, and its first plan made
    schedule::Schedule schedule; // what a view draws: no sky points or plans
    std::optional<int> current;  // the index in schedule.passes being followed
};

// The schedule's pass that is the one followed: the same target, taken,
// starting within a second of it (a plan made again keeps its passes, but
// not necessarily their places in the list).
bool isFollowedPass(const schedule::ScheduledPass &pass, const schedule::ScheduledPass &followed);
std::optional<int> followedIndex(const schedule::Schedule &schedule, const std::optional<schedule::ScheduledPass> &followed);

} // namespace slew::face
