// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The station's schedule: which passes of several targets, given in
// priority order, the rotator follows over the next hours.
//
// Passes are taken by priority, greedily: every pass of the first target,
// then those of the second that fit between them, and so on. A pass is
// taken only when
//   - it clears the station's horizon mask (sky::Site::horizon) and the
//     minimum elevation: one that never does is dropped, "below the horizon";
//   - its satellite's elements are not too old at its AOS;
//   - the planner (tracking/passplanner.h) finds a path for it;
//   - it does not overlap a pass already taken, a guard time apart: the
//     higher priority keeps its pass, the lower loses it, with the other's
//     name in the reason;
//   - the rotator, by its own speed and acceleration, can get from where
//     the pass before leaves it to this pass's AOS point in the time
//     between them, and from this pass's end to the AOS point of the pass
//     after (a pass already under way when the schedule starts is joined
//     late). Each path is planned from where the pass before leaves the
//     antenna, so a 450° rotator uses its overlap instead of turning back.
// A long target (the sun, the moon, a radio source, a fixed direction) is
// fitted into the gaps instead: each piece of its time above the horizon
// that overlaps nothing and lasts at least the shortest piece is taken.
//
// Every pass is kept with its decision: taken, or dropped and why.
// Pinned passes (the one in progress when the plan is made again) are taken
// first, whatever their priority, so a new plan never takes the rotator
// away from under a pass it is following.
//
// Pure functions: the same targets, elements, station and rotator give the
// same schedule. planSchedule() predicts, samples and plans every pass
// (the moon takes a good part of a second a day): callers run it on a
// worker thread.

#include "tracking/passplanner.h"
#include "tracking/tracktarget.h"

#include "sky/elementage.h"
#include "sky/passes.h"
#include "sky/site.h"

#include <QList>
#include <QString>
#include <QStringList>

#include <atomic>
#include <optional>

namespace slew::schedule {

enum class DropReason {
    None,            // taken
    Overlap,         // a higher priority's pass is there
    Unreachable,     // the rotator cannot get there in time
    BelowHorizon,    // it never clears the horizon mask
    StaleElements,   // its elements are too old at AOS
    NoPlan,          // no path the rotator can drive
    NoRoomLeft,      // a long target with no gap long enough
};

// Where the antenna is, in the rotator's own terms (an azimuth past 360°,
// an elevation past 90° is the flip).
struct AntennaPoint {
    double azimuth = 0;
    double elevation = 0;
};

struct ScheduledPass {
    int priority = 0;        // the target's place in the list, 0 the first (highest)
    QString target;          // its name
    int norad = 0;           // 0 for the sun, the moon, a radio source or a fixed direction
    sky::Pass pass;          // as predicted on the station's horizon (a hidden one: without it)
    double startJulian = 0;  // what is taken: the pass, or a long target's piece in a gap
    double endJulian = 0;
    bool taken = false;
    DropReason reason = DropReason::None;
    QString why;             // a dropped pass's reason; a piece's "from … to …, between …"
    bool pinned = false;     // in progress when planned: kept whatever else changed
    // Of a planned pass (taken, or dropped for overlap or reach):
    AntennaPoint first, last;     // where its path starts and ends
    double predictedWorstDeg = 0; // the planner's worst pointing error
    QList<tracking::SkyPoint> points; // the sky from startJulian, seconds from it
    tracking::PassPlan plan;

    double durationSeconds() const { return (endJulian - startJulian) * sky::kSecondsPerDay; }
};

struct ScheduleSettings {
    double startJulian = 0;
    double hours = 24;
    double minElevationDeg = 0;
    // Between one pass's end and the next one's start, besides the move.
    double guardSeconds = 30;
    // A satellite whose elements are further than this from a pass's AOS:
    // dropped (a LEO's prediction is minutes off after a few weeks).
    double maxElementAgeDays = sky::kElementAgeLimitDays;
    // The least of a long target's time worth a place between passes.
    double shortestPieceSeconds = 300;
    // Where the antenna stands at the start, when known: the first pass
    // must be reachable from there.
    std::optional<AntennaPoint> antennaAt;
};

struct Schedule {
    ScheduleSettings settings;
    QStringList targets;             // their names, in priority order
    QList<ScheduledPass> passes;     // by start, taken and dropped
    QStringList notes;               // about targets, e.g. one with no pass at all

    int takenCount() const;
    int droppedCount() const;
    // The taken pass going on at `julian`, or the next one; none after the last.
    std::optional<ScheduledPass> takenAtOrAfter(double julian) const;
};

// Predicts, samples and plans every pass of every target in the settings'
// window and arranges them as above. `pinned` are taken first (their
// points and plan as they were). `stop`, when set true, ends the work early
// with what is arranged so far.
Schedule planSchedule(const QList<tracking::TrackTarget> &targets, const sky::Site &station,
                      const tracking::RotatorReach &reach, const ScheduleSettings &settings,
                      const QList<ScheduledPass> &pinned = {}, const std::atomic<bool> *stop = nullptr);

// The arranging alone, on passes already predicted and planned (each
// target's in time order, the targets by priority): for tests and the
// benchmark. Dropped candidates (below the horizon, stale, no plan) pass
// through as they are.
Schedule arrangeSchedule(const QList<QList<ScheduledPass>> &candidatesByPriority, const tracking::RotatorReach &reach,
                         const ScheduleSettings &settings, const QList<ScheduledPass> &pinned = {});

// How long the rotator takes from one position to another, both axes at
// once, each at its speed and acceleration.
double moveSeconds(const tracking::RotatorReach &reach, const AntennaPoint &from, const AntennaPoint &to);

} // namespace slew::schedule
