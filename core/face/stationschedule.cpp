// SPDX-License-Identifier: GPL-3.0-or-later
#include "stationschedule.h"

#include <cmath>

namespace slew::face {

bool isFollowedPass(const schedule::ScheduledPass &pass, const schedule::ScheduledPass &followed)
{
    return pass.taken && pass.target == followed.target && std::abs(pass.startJulian - followed.startJulian) * 86400.0 < 1.0;
}

std::optional<int> followedIndex(const schedule::Schedule &schedule, const std::optional<schedule::ScheduledPass> &followed)
{
    if (!followed)
        return std::nullopt;
    for (qsizetype i = 0; i < schedule.passes.size(); ++i) {
        if (isFollowedPass(schedule.passes[i], *followed))
            return int(i);
    }
    return std::nullopt;
}

} // namespace slew::face
