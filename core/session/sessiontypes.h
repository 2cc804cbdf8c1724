// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The plain values the session deals in, which its signals carry and
// widgets show: axes, status and error bits, telemetry, capabilities, a
// pointing target and a command's result.

#include <QMetaType>
#include <QString>

#include <cmath>
#include <cstdint>
#include <limits>

namespace slew::session {

inline constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();

enum class Axis : std::uint8_t { Azimuth, Elevation };
enum class Axes : std::uint8_t { Azimuth = 1, Elevation = 2, Both = 3 };

// GS bits, per axis (the Easycomm III derivative: azimuth in the low byte, elevation in the high).
enum AxisStatusBit : std::uint8_t { StatusIdle = 1, StatusMoving = 2, StatusPointing = 4, StatusError = 8 };

// GE bits. Which reading is in force depends on the dialect: docs/protocol.md.
enum ErrorBit : std::uint16_t {
    ErrorNone = 1,           // SatNOGS / the Easycomm III derivative: "no error"
    ErrorSensor = 2,
    ErrorHoming = 4,
    ErrorMotor = 8,
    ErrorOverTemperature = 12, // SatNOGS reports 12 (motor | homing bits)
    ErrorWatchdog = 16,
};

// What a command did: sent (true), or refused, and then nothing was sent;
// refusal says why (commandRefused() carries the same words).
struct CommandResult {
    QString refusal;
    explicit operator bool() const { return refusal.isEmpty(); }
};

// A position the rotator was sent to (azimuth as commanded, mechanical).
struct PointingTarget {
    double azimuth = 0.0;
    double elevation = 0.0;
};

struct StatusWord {
    quint16 raw = 0;
    bool valid = false;
    quint8 azimuth() const { return quint8(raw & 0xff); }
    quint8 elevation() const { return quint8(raw >> 8); }
    // A controller that reports one status for both axes sets only the low byte.
    bool isPerAxis() const { return elevation() != 0; }
    bool anyError() const { return valid && ((azimuth() | elevation()) & StatusError); }
    bool anyMoving() const { return valid && ((azimuth() | elevation()) & StatusMoving); }
    bool idle() const { return valid && !anyMoving(); }
};

// Readable list of GE bits: "sensor error, motor error". Empty for no error.
QString describeErrorFlags(int ge);
// "moving, pointing" for one axis' GS bits.
QString describeAxisStatus(quint8 bits);

struct Telemetry {
    qint64 timeMs = 0;               // when the last value arrived (ms since epoch)
    double temperature = kUnknown;   // IP0, °C
    int azEndStop = -1;              // IP1 bits: 1 CCW, 2 CW; -1 unknown
    int elEndStop = -1;              // IP2 bits: 1 lower, 2 upper
    double azLoad = kUnknown;        // IP5
    double elLoad = kUnknown;        // IP6
    double azVelocity = kUnknown;    // IP7, °/s
    double elVelocity = kUnknown;    // IP8, °/s
};

struct Capabilities {
    bool probed = false;     // the probe has finished
    bool positionFeedback = false; // answers AZ/EL queries
    bool version = false;    // VE
    bool status = false;     // GS
    bool errors = false;     // GE
    bool inputs = false;     // IP
    bool config = false;     // CR/CW
    bool encoders = false;   // \?ENC
    bool velocity = false;   // VL/VR/VU/VD (dialect)
    bool moveCommands = false; // ML/MR/MU/MD (dialect)
    bool park = false;       // PARK (dialect)
    bool reset = false;      // RESET (dialect)
    bool stop = false;       // SA/SE (dialect)
};

} // namespace slew::session

Q_DECLARE_METATYPE(slew::session::Telemetry)
Q_DECLARE_METATYPE(slew::session::Capabilities)
Q_DECLARE_METATYPE(slew::session::StatusWord)
