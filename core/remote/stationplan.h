// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The plan of the pass a station is waiting for or following, as it
// publishes it on `slew/NAME/plan` (retained): the target's track across the
// sky and the antenna's planned path, so a remote window draws the pass on
// its plot as the local window does. One JSON object:
//
//   {"unix_ms":…, "target":"ISS (ZARYA)", "norad":25544,
//    "aos_ms":…, "tca_ms":…, "los_ms":…, "max_el":56.1,
//    "planned_worst_deg":0.12, "flipped":false, "over_the_top":false,
//    "unwinds":0, "az_turn_start":0, "az_turn_end":360,
//    "sky":[[az,el],…], "path":[[az,el],…]}
//
// No target: no pass ahead (tracking stopped). The reader checks every
// field (jsonfields.h) and takes a message whole or not at all. Pure code.

#include "face/stationplan.h"

#include <QByteArray>
#include <QList>
#include <QPointF>
#include <QString>

#include <optional>

namespace slew::remote {

// A pass sampled every second for a quarter of an hour is 900 points: the
// encoder keeps every n-th (and the last) so each list has at most this.
inline constexpr int kMostPlanPoints = 400;
inline constexpr int kLargestPlanMessage = 64 * 1024;

QByteArray encodeStationPlan(const face::StationPlan &plan);
std::optional<face::StationPlan> parseStationPlan(const QByteArray &payload, QString *error);

// Every n-th point of `points` and the last, at most `most` in all.
QList<QPointF> thinPoints(const QList<QPointF> &points, int most);

} // namespace slew::remote
