// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A station's state as it publishes it on `slew/NAME/state` (retained):
// everything a window needs to show a station it does not run. A flat JSON
// object, so a shell's `mosquitto_sub | jq .az` reads it too:
//
//   {"unix_ms":…, "time":"2026-11-26T10:00:00.123Z", "link":"connected",
//    "az":120.0, "el":30.0, "stale":false, "target_az":…, "target_el":…,
//    "moving":true, "az_status":"moving, pointing", "el_status":"at rest",
//    "axis_error":false, "homing_failed":false, "controller_errors":"…", "az_min":0, "az_max":450, "el_min":0, "el_max":180,
//    "park_az":…, "park_el":…, "azimuth_only":false,
//    "dialect":"Easycomm III", "probed":true, "jog_speed":true,
//    "can_home":true, "park_command":true,
//    "tracking":"tracking", "tracking_target":"ISS (ZARYA)", "tracking_norad":25544,
//    "pass_aos_ms":…, "pass_los_ms":…, "pass_max_el":56.1,
//    "alarms":["…"], "severe":false, "operator_hold":false,
//    "controller":"…", "slew":"0.1.0",
//    "radio_link":"connected", "radio_held":false, "radio_steering":true,
//    "radio_rx_hz":435123456, "radio_tx_hz":145912345}
//
// The radio's fields come together, from radio_link on ("none": no radio
// set); a station older than them leaves them all out.
//
// Unknown values are left out (JSON has no NaN). The reader checks every
// field (jsonfields.h) and takes a message whole or not at all. Pure code.

#include "face/stationstate.h"

#include "model/rotatorlimits.h"

#include <QByteArray>
#include <QPointF>
#include <QStringList>

#include <optional>

namespace slew::remote {

inline constexpr int kLargestStateMessage = 16 * 1024;
inline constexpr double kMostClockRate = 100.0; // above any rehearsal's (StationClock::kMaxRate)

QByteArray encodeStationState(const face::StationState &state);
std::optional<face::StationState> parseStationState(const QByteArray &payload, QString *error);

// The link states' names, for the JSON and for people.
bool isLinkStateName(const QString &name);
// A link state's name, or "none" (the station has no radio).
bool isRadioLinkName(const QString &name);
bool isTrackingStateName(const QString &name);

} // namespace slew::remote
