// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The SPID protocol (Alfa Rot2Prog, Rot1Prog, MD-01/02 in ROT2 mode): fixed
// binary frames, not lines. Pure functions: no I/O, no Qt signals.
//
// Host to controller, 13 bytes:  0x57 H1 H2 H3 H4 PH V1 V2 V3 V4 PV K 0x20
// Controller to host, 12 bytes:  0x57 H1 H2 H3 H4 PH V1 V2 V3 V4 PV 0x20
// Rot1Prog to host, 5 bytes:     0x57 H1 H2 H3 0x20
//
// In a command the digits are ASCII; in a reply they are raw values 0..9.
// docs/protocol.md "SPID" has the table and the choices made here.

#include "dialect.h"

#include <QByteArray>

#include <cstdint>

namespace slew::protocol::spid {

constexpr char kStart = 0x57; // 'W': the first byte of every frame
constexpr char kEnd = 0x20;   // ' ': the last byte of every frame
constexpr int kCommandSize = 13;
constexpr int kReplySize = 12;
constexpr int kRot1ReplySize = 5;

// K, the command byte of a host frame.
enum class Command : std::uint8_t {
    Stop = 0x0F,
    Status = 0x1F,
    Set = 0x2F,
    Move = 0x14, // MD-01/02 only: the directions in H1
};

// MD-01/02 move directions, the bits of H1 in a Move frame.
namespace MoveBit {
constexpr int Left = 0x01;
constexpr int Right = 0x02;
constexpr int Up = 0x04;
constexpr int Down = 0x08;
} // namespace MoveBit

// The mechanical ranges every SPID controller accepts (Hamlib's caps for
// all three models); Rot1Prog has no elevation.
constexpr double kMinAzimuth = -180.0;
constexpr double kMaxAzimuth = 540.0;
constexpr double kMinElevation = -20.0;
constexpr double kMaxElevation = 210.0;

// Pulses per degree a controller may report in PH/PV: 1, 2 or 4, and 10,
// since a reply's digits are tenths of a degree whatever the resolution.
bool isResolution(int pulsesPerDegree);

// Why a position cannot be sent (nullptr when it can): not a number, or
// outside the ranges above. Rot1Prog ignores the elevation.
const char *positionRefusal(double azimuth, double elevation, Dialect d);

// An encoded frame, or why there is none (bytes empty, refusal set).
struct Encoded {
    QByteArray bytes;
    const char *refusal = nullptr;
    bool ok() const { return refusal == nullptr; }
};

// Host frames. A set is `H = PH × (360 + az)` as four ASCII digits, rounded
// to the nearest pulse; Rot1Prog takes whole degrees in H1..H3 with H4 '0'
// and no resolution bytes, as Hamlib's model 902 writes it.
Encoded encodeSet(double azimuth, double elevation, Dialect d, int azimuthPulses = 1, int elevationPulses = 1);
QByteArray encodeStatus();
QByteArray encodeStop();
// MD-01/02 only; directions is a set of MoveBit values (one per axis at most).
Encoded encodeMove(int directions, Dialect d);

// A controller's reply to status, stop (and, MD-01/02, set): tenths of a
// degree as raw digits. For the simulator and for tests; the position must
// be inside the ranges (it is clamped to what four digits hold otherwise).
QByteArray encodeReply(double azimuth, double elevation, Dialect d, int azimuthPulses, int elevationPulses);

// How many bytes a reply of this dialect has (12, Rot1Prog 5).
int replySize(Dialect d);

} // namespace slew::protocol::spid
