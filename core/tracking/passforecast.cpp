// SPDX-License-Identifier: GPL-3.0-or-later
#include "passforecast.h"

#include <algorithm>

namespace slew::tracking {

namespace {

// A pass already up when `window` opens, as it really is: the AOS it rose
// at and its highest point, from the pass the window before reports whole
// (a search reports whole every pass that begins before its end). Looked
// for up to `lookBackDays` back; a pass that rose before stays clipped.
sky::Pass wholePass(const TargetSky &target, const sky::Site &station, const sky::PassWindow &window, sky::Pass p,
                    double lookBackDays)
{
    if (!p.aosClipped || !(lookBackDays > 0.0))
        return p;
    sky::PassWindow before = window;
    before.startJulian = window.startJulian - lookBackDays;
    before.endJulian = window.startJulian;
    const QList<sky::Pass> earlier = target.passes(station, before);
    if (earlier.isEmpty() || earlier.back().los.julian < window.startJulian)
        return p;
    const sky::Pass &whole = earlier.back();
    p.aos = whole.aos;
    p.aosClipped = whole.aosClipped;
    if (whole.tca.elevationDeg > p.tca.elevationDeg)
        p.tca = whole.tca;
    return p;
}

} // namespace

QList<PlannedPass> forecastPasses(const TargetSky &target, const sky::Site &station, const sky::PassWindow &window,
                                  const RotatorReach &reach, double lookBackDays)
{
    QList<PlannedPass> planned;
    for (const sky::Pass &p : target.passes(station, window)) {
        if (window.stop && window.stop->load())
            break; // told to give up: the search is of no use any more
        const double from = p.aos.julian; // the window's start for a pass already up
        PlannedPass one{wholePass(target, station, window, p, lookBackDays), from, target.sample(station, p, from), {}};
        one.plan = planPass(one.points, reach);
        planned.append(std::move(one));
    }
    return planned;
}

std::optional<PlannedPass> forecastNextPass(const TargetSky &target, const sky::Site &station,
                                            const sky::PassWindow &window, double nowJulian, double marginSeconds,
                                            const RotatorReach &reach, const PlannerOptions &options,
                                            double lookBackDays)
{
    for (const sky::Pass &p : target.passes(station, window)) {
        if (window.stop && window.stop->load())
            return std::nullopt;
        if (p.los.julian <= nowJulian + marginSeconds / sky::kSecondsPerDay)
            continue;
        const double from = std::max(p.aos.julian, nowJulian);
        PlannedPass next{wholePass(target, station, window, p, lookBackDays), from, target.sample(station, p, from), {}};
        next.plan = planPass(next.points, reach, options);
        return next;
    }
    return std::nullopt;
}

std::optional<PlannedPass> forecastPassBetween(const TargetSky &target, const sky::Site &station,
                                               const sky::PassWindow &window, double nowJulian, double marginSeconds,
                                               double fromJulian, double untilJulian, const RotatorReach &reach,
                                               const PlannerOptions &options, double lookBackDays)
{
    const double margin = marginSeconds / sky::kSecondsPerDay;
    const double until = std::min(untilJulian, window.endJulian);
    for (sky::Pass p : target.passes(station, window)) {
        if (window.stop && window.stop->load())
            return std::nullopt;
        const double from = std::max({p.aos.julian, nowJulian, fromJulian});
        const double to = std::min(p.los.julian, until);
        if (to <= from + margin)
            continue;
        // Sampled to the end of what was taken: the pass's LOS, or the
        // piece's end for a long target.
        if (to < p.los.julian) {
            p.los.julian = to;
            p.losClipped = true;
        }
        PlannedPass next{wholePass(target, station, window, p, lookBackDays), from, target.sample(station, p, from), {}};
        next.plan = planPass(next.points, reach, options);
        return next;
    }
    return std::nullopt;
}

} // namespace slew::tracking
