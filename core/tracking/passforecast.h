// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A target's passes, each sampled and planned for this rotator: what the
// Tracking tab lists and what the station service tracks next.
//
// Sampling and planning cost: the moon's theory is 1.7 ms a position, and
// a day of its passes took 0.6 s to sample and plan. So the callers run
// these functions on a worker thread (QtConcurrent) and take the result
// back on theirs; they are pure (every input is a copy or const, nothing
// is cached between calls), which is what makes that safe.

#include "passplanner.h"
#include "tracktarget.h"

#include "sky/passes.h"

#include <QList>

#include <optional>

namespace slew::tracking {

struct PlannedPass {
    sky::Pass pass;
    double fromJulian = 0;    // where the samples start: the AOS, or later for a pass under way
    bool underWay() const { return pass.aosClipped || fromJulian > pass.aos.julian; }
    QList<SkyPoint> points;   // seconds from fromJulian
    PassPlan plan;
};

// Every pass in `window`, planned, sampled from its AOS or, for one already
// up when the window opens, from the window's start. Such a pass is given
// the AOS it rose at, looked for up to `lookBackDays` before the window
// (still clipped, and so marked, when it rose before that).
QList<PlannedPass> forecastPasses(const TargetSky &target, const sky::Site &station, const sky::PassWindow &window,
                                  const RotatorReach &reach, double lookBackDays = 0.0);

// The first pass in `window` still up `marginSeconds` after `nowJulian`,
// sampled from its AOS or from now if it is under way, and planned from
// where the antenna is; none if there is no such pass. One already up when
// the window opens has its true AOS and highest point, as forecastPasses.
std::optional<PlannedPass> forecastNextPass(const TargetSky &target, const sky::Site &station,
                                            const sky::PassWindow &window, double nowJulian, double marginSeconds,
                                            const RotatorReach &reach, const PlannerOptions &options,
                                            double lookBackDays = 0.0);

// The schedule's pass (schedule/schedule.h): the first pass in `window`
// still up `marginSeconds` after `nowJulian`, sampled from the latest of its
// AOS, now and `fromJulian` to the earliest of its LOS and `untilJulian` (a
// long target's piece between other passes), and planned. A pass already
// up when the window opens is reported as it really is (its AOS and
// highest point, looked for up to `lookBackDays` back), as forecastNextPass
// does: a schedule joined under way records the pass, not the join.
std::optional<PlannedPass> forecastPassBetween(const TargetSky &target, const sky::Site &station,
                                               const sky::PassWindow &window, double nowJulian, double marginSeconds,
                                               double fromJulian, double untilJulian, const RotatorReach &reach,
                                               const PlannerOptions &options, double lookBackDays = 0.0);

} // namespace slew::tracking
