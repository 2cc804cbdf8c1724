// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A schedule as people and programs read it: a line a pass for the log and
// `slew --schedule`, and JSON for `slew --schedule --json` (and whatever
// publishes the plan).
//
//   2018-01-22 09:17:51–09:25:04 UTC  FLOCK 2P-1 [1]  max 56.2°  taken (plan worst 0.22°)
//   2018-01-22 09:19:10–09:29:40 UTC  NOAA 18 [2]  max 40.1°  dropped: overlaps FLOCK 2P-1 (priority 1, …)

#include "schedule.h"

#include <QJsonObject>
#include <QString>

namespace slew::schedule {

// "overlap", "unreachable", "below horizon", …: the JSON's word for a reason.
QString reasonWord(DropReason reason);

// One pass, as above.
QString describeScheduledPass(const ScheduledPass &pass);

// "7 passes taken, 4 dropped, 2018-01-22 09:00 to 2018-01-23 09:00 UTC"
QString describeScheduleSummary(const Schedule &schedule);

// The whole schedule: its window, targets by priority, every pass.
QJsonObject scheduleToJson(const Schedule &schedule);

} // namespace slew::schedule
