// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A face's schedule request (face/schedulerequest.h) as the Station's
// schedule options (schedulerunner.h): the same three numbers, with the
// same defaults, which the compiler holds to.

#include "schedulerunner.h"

#include "face/schedulerequest.h"

namespace slew::station {

static_assert(ScheduleOptions{}.hours == face::ScheduleRequest{}.hours
                  && ScheduleOptions{}.minElevationDeg == face::ScheduleRequest{}.minElevationDeg
                  && ScheduleOptions{}.guardSeconds == face::ScheduleRequest{}.guardSeconds,
              "a face's schedule and the Station's take the same defaults");

inline ScheduleOptions scheduleOptions(const face::ScheduleRequest &request)
{
    ScheduleOptions options;
    options.hours = request.hours;
    options.minElevationDeg = request.minElevationDeg;
    options.guardSeconds = request.guardSeconds;
    return options;
}

} // namespace slew::station
