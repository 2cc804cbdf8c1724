// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The topics of one station on the broker, all under `slew/NAME/`:
//
//   online     retained  "true" while connected; "false" as its will and on a clean exit
//   state      retained  JSON: link, position, target, tracking and pass, alarms, versions
//   telemetry            JSON, up to the poll rate: position, speed, load, temperature,
//                        GS/GE, pointing error, Doppler error
//   command              JSON, to the station: goto, stop, park, home, track, untrack, jog
//   reply                JSON, from the station: the answer to each command's id
//   schedule   retained  JSON: the schedule it runs, every pass with its decision (stationschedule.h)
//   plan       retained  JSON: the pass ahead, its sky and the antenna's planned path (stationplan.h)
//
// A broker's access list grants these per account (docs/remote.md):
// watchers read `slew/+/#` and write nothing; operators also write
// `slew/+/command`; a station writes its own `slew/NAME/#` and reads its
// `command`. Pure code.

#include <QString>

#include <optional>

namespace slew::remote {

inline constexpr char kTopicRoot[] = "slew";

enum class StationTopic { Online, State, Telemetry, Command, Reply, Schedule, Plan };

// "slew/NAME/state".
QString stationTopic(const QString &stationName, StationTopic topic);
// "slew/NAME/#": everything one station says.
QString stationFilter(const QString &stationName);
// "slew/+/online" and "slew/+/state": how the network view finds stations.
QString everyStationFilter(StationTopic topic);

struct ParsedTopic {
    QString stationName;
    StationTopic topic;
};
// Which station and topic `topic` is, if it is one of ours with a name
// checkStationName() accepts.
std::optional<ParsedTopic> parseStationTopic(const QString &topic);

} // namespace slew::remote
