// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A command to a station over MQTT, and the station's reply, as JSON:
//
//   {"id":"7","cmd":"goto","az":120,"el":30}
//   {"id":"8","cmd":"stop"}          park, home, untrack likewise
//   {"id":"9","cmd":"track","target":"ISS (ZARYA)","min_el":5}
//   {"id":"10","cmd":"jog","az_speed":-5.0,"el_speed":0,"lease_ms":1000}
//   {"id":"11","cmd":"schedule","targets":["FLOCK 2P-1","43218"],"hours":24,"min_el":0,"guard_s":30}
//   {"id":"12","cmd":"unschedule"}
//   {"id":"13","cmd":"radio_hold","held":true}
//   {"id":"14","cmd":"schedule_preview","targets":["AO-91","sun"],"hours":24}
//   {"id":"15","cmd":"clear_fault"}
//
//   {"id":"7","ok":true}
//   {"id":"7","ok":false,"error":"azimuth 999.0° is outside …"}
//   {"id":"14","ok":true,"preview":{"targets":[…],"start_ms":…,"passes":[…]}}
//
// A jog is a lease: speeds in degrees a second (signed: + is clockwise and
// up), held for lease_ms (at most a second) and stopped by the station
// unless renewed. A schedule's targets are named as track's, in priority
// order, its numbers as face/schedulerequest.h takes them (each left out
// takes its default); a preview (stationschedule.h) is a schedule's plan
// made and not run, answered with the plan. Every field is checked (jsonfields.h); a command with
// a fault is refused whole and does nothing. Pure code.

#include "face/schedulerequest.h"
#include "stationschedule.h"

#include <QByteArray>
#include <QMetaType>
#include <QString>
#include <QStringList>

#include <optional>

namespace slew::remote {

inline constexpr int kLongestCommandId = 64;     // characters
inline constexpr int kLongestTrackTarget = 100;  // characters, a schedule's each too
// A schedule of as many targets as a station publishes (kMostScheduleTargets),
// each as long as it may be in three-byte characters, fits.
inline constexpr int kLargestCommand = 32 * 1024; // bytes
static_assert(kMostScheduleTargets * (3 * kLongestTrackTarget + 3) + 1024 <= kLargestCommand);
inline constexpr int kLongestJogLeaseMs = 1000;  // a lost network stops a jog within a second
inline constexpr int kShortestJogLeaseMs = 100;
inline constexpr double kFastestJog = 90.0;      // degrees a second, either sign

struct RemoteCommand {
    enum class Kind { Goto, Stop, Park, Home, Track, Untrack, Jog, Schedule, SchedulePreview, Unschedule, RadioHold, ClearFault };
    QString id; // empty: no reply wanted
    Kind kind = Kind::Stop;
    double azimuth = 0, elevation = 0;           // Goto
    double azSpeed = 0, elSpeed = 0;             // Jog
    int leaseMs = kLongestJogLeaseMs;            // Jog
    QString target;                              // Track
    std::optional<double> minElevation;          // Track
    QStringList targets;                         // Schedule(Preview), by priority
    face::ScheduleRequest schedule;              // Schedule(Preview)
    bool held = false;                           // RadioHold
};

// "goto", "stop", ...
QString commandName(RemoteCommand::Kind kind);

struct ParsedCommand {
    std::optional<RemoteCommand> command;
    QString id;    // the id, when one could be read, even from a refused command
    QString error; // why it was refused
};
ParsedCommand parseRemoteCommand(const QByteArray &payload);
QByteArray encodeRemoteCommand(const RemoteCommand &command);

struct RemoteReply {
    QString id;
    bool ok = false;
    QString error;
    std::optional<face::SchedulePreview> preview; // the answer to a schedule_preview
};
inline constexpr int kLongestReplyError = 400;
// A reply is a line, or a preview's plan: as large as a published schedule.
inline constexpr int kLargestReply = kLargestScheduleMessage + 64 * 1024;
QByteArray encodeRemoteReply(const RemoteReply &reply);
std::optional<RemoteReply> parseRemoteReply(const QByteArray &payload, QString *error);

} // namespace slew::remote

Q_DECLARE_METATYPE(slew::remote::RemoteReply)
