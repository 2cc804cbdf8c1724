// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A station's state as it publishes it on `slew/NAME/state` (retained):
// everything a window needs to show a station it does not run. A flat JSON
// object, so a shell's `mosquitto_sub | jq .az` reads it too:
//
//   {"unix_ms":…, "time":"2026-11-26T10:00:00.123Z", "link":"connected",
//    "az":120.0, "el":30.0, "stale":false, "target_az":…, "target_el":…,
//    "moving":true, "az_min":0, "az_max":450, "el_min":0, "el_max":180,
//    "park_az":…, "park_el":…, "azimuth_only":false,
//    "tracking":"tracking", "tracking_target":"ISS (ZARYA)", "tracking_norad":25544,
//    "pass_aos_ms":…, "pass_los_ms":…, "pass_max_el":56.1,
//    "alarms":["…"], "severe":false, "operator_hold":false,
//    "controller":"…", "slew":"0.1.0"}
//
// Unknown values are left out (JSON has no NaN). The reader checks every
// field (jsonfields.h) and takes a message whole or not at all. Pure code.

#include "model/rotatorlimits.h"

#include <QByteArray>
#include <QPointF>
#include <QStringList>

#include <optional>

namespace slew::remote {

struct StationState {
    qint64 unixMs = 0;
    // The station's own clock at unixMs, when it is not the wall clock (a
    // rehearsal), and how fast it runs (0 while paused): the pass times
    // below are in its time, and a viewer counts down by it.
    std::optional<qint64> clockMs;
    double clockRate = 1.0;
    // disconnected, connecting, connected, reconnecting: the rotator's link.
    QString link = QStringLiteral("disconnected");
    QString linkDetail; // why it failed, when it did
    std::optional<QPointF> position; // az, el in the pointing frame
    bool stale = true;
    std::optional<QPointF> target;
    bool moving = false;
    model::RotatorLimits limits;
    std::optional<QPointF> park;
    bool azimuthOnly = false;
    // off, planning, waiting, tracking, done.
    QString tracking = QStringLiteral("off");
    QString trackingTarget;
    std::optional<int> trackingNorad; // a satellite's catalogue number, up to nine digits
    std::optional<qint64> passAosMs, passLosMs;
    std::optional<double> passMaxElevation;
    QStringList alarms;
    bool severe = false;
    bool operatorHold = false;
    QString controllerVersion;
    QString slewVersion;
};

inline constexpr int kLargestStateMessage = 16 * 1024;
inline constexpr int kMostAlarms = 32;
inline constexpr double kMostClockRate = 100.0; // above any rehearsal's (StationClock::kMaxRate)

QByteArray encodeStationState(const StationState &state);
std::optional<StationState> parseStationState(const QByteArray &payload, QString *error);

// The link states' names, for the JSON and for people.
bool isLinkStateName(const QString &name);
bool isTrackingStateName(const QString &name);

} // namespace slew::remote
