// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A station's schedule as it publishes it on `slew/NAME/schedule`
// (retained): its window, the targets by priority, every pass taken or
// dropped with the reason, and the one being followed, so a remote window
// shows the time line the local window's Schedule page shows. One JSON
// object, times in milliseconds since 1970 as the state's:
//
//   {"unix_ms":…, "clock_ms":…, "clock_rate":1, "running":true, "start_ms":…, "end_ms":…, "min_el":0,
//    "guard_s":30, "targets":["FLOCK 2P-1","NOAA 18"], "notes":[…],
//    "current":3,
//    "passes":[{"target":"FLOCK 2P-1","priority":1,"norad":43218,
//               "aos_ms":…,"tca_ms":…,"los_ms":…,"start_ms":…,"end_ms":…,
//               "max_el":56.2,"aos_az":350.1,"los_az":170.3,"taken":true,
//               "reason":"taken","why":"…","planned_worst_deg":0.2,
//               "in_progress":false}, …]}
//
// clock_ms is the station clock's time as the message is made, which a
// rehearsal (`--clock-start`, `--clock-rate`) sets apart from unix_ms.
// Not running: no passes. Running but still making its first plan: no
// window and no passes yet. The reader checks every field (jsonfields.h) and
// takes a message whole or not at all. Pure code.

#include "face/schedulepreview.h"
#include "face/stationschedule.h"

#include "schedule/schedule.h"

#include <QByteArray>
#include <QJsonObject>

#include <optional>

namespace slew::remote {

// A day of a dozen satellites is a few hundred passes.
inline constexpr int kMostScheduledPasses = 500;
inline constexpr int kMostScheduleTargets = 100;
inline constexpr int kLargestScheduleMessage = 512 * 1024;

// `current` is matched to a pass of `schedule` by target and start.
QByteArray encodeStationSchedule(qint64 unixMs, qint64 clockMs, double clockRate, bool running, const schedule::Schedule &schedule,
                                 const std::optional<schedule::ScheduledPass> &current);
std::optional<face::StationSchedule> parseStationSchedule(const QByteArray &payload, QString *error);

// A schedule's preview (a reply's "preview"): the targets as the station
// named them, then the plan's window, targets, notes and passes as above:
//   {"named":[{"asked":"AO-91","name":"FOX-1B (AO-91)","norad":43017},
//             {"asked":"NO SUCH","problem":"no satellite 'NO SUCH' …"}],
//    "start_ms":…, "end_ms":…, "targets":["FOX-1B (AO-91)"], "passes":[…]}
// or, with no plan made, "not_planned":"a schedule needs the station's place".
QJsonObject schedulePreviewObject(const face::SchedulePreview &preview);
std::optional<face::SchedulePreview> readSchedulePreview(const QJsonObject &object, QString *error);

} // namespace slew::remote
