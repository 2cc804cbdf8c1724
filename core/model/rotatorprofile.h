#pragma once
// Everything Slew knows about one rotator: how to reach it, which dialect it
// speaks, how far it may turn, where it parks and its tuned gains. Saved as
// JSON (atomically) by the operator window and the setup wizard.

#include "rotatorlimits.h"
#include "protocol/dialect.h"
#include "protocol/firmware.h"

#include <QJsonObject>
#include <QString>

#include <array>
#include <optional>

namespace slew::model {

struct PidGains {
    double kp = 0.0;
    double ki = 0.0;
    double kd = 0.0;
    friend bool operator==(const PidGains &, const PidGains &) = default;
};

// How the rotator moves, for the tracker (docs/tracking.md): what the setup
// wizard's tuning steps measured, or a G-5500's figures until it has.
struct RotatorMotion {
    enum class Drive { Servo, Relay };
    double azSpeedDegS = 6.2;    // the fastest each axis turns
    double elSpeedDegS = 2.7;
    double azAccelDegS2 = 12.0;  // how fast it gets up to speed
    double elAccelDegS2 = 6.0;
    double responseDelayS = 0.1; // from a command sent to the axis starting to move
    // A relay drive switches its motor on and off; a servo follows a speed.
    Drive drive = Drive::Servo;
    // The tracker's minimum step (deadband); 0: the drive's default.
    double trackStepDeg = 0.0;
    friend bool operator==(const RotatorMotion &, const RotatorMotion &) = default;
};

struct RotatorProfile {
    QString name = QStringLiteral("Simulator");
    QString uri = QStringLiteral("sim:");
    protocol::Dialect dialect = protocol::Dialect::Easycomm3;
    // The controller's firmware, where its quirks matter (protocol/firmware.h):
    // how close it stops, whether its status shows motion, what it lacks.
    protocol::Firmware firmware = protocol::Firmware::Generic;
    // How close the controller brings each axis before it lets go, where it
    // was built otherwise than its firmware's default (K3NG's
    // AZIMUTH_TOLERANCE set to 1°): 0..10°. Unset: the firmware's.
    std::optional<double> stopToleranceAzDeg;
    std::optional<double> stopToleranceElDeg;
    RotatorLimits limits;
    double parkAz = 0.0;
    double parkEl = 90.0;
    bool southStop = false;          // the azimuth stop is at south (Micro-2g program set-up)
    std::optional<PidGains> azGains; // as last written with CW1..CW3
    std::optional<PidGains> elGains; // CW4..CW6
    double deadbandDeg = 0.5;        // a remote target this close to the last one is not re-sent
    int pollHz = 10;
    // How often a rotator at rest is polled: nothing moved and nobody asked
    // for a while (session/pollpace.h). 0.1 Hz to pollHz; the station then
    // wakes about once a second instead of ten times.
    double restPollHz = 1.0;

    // Calibration: where the antenna points is the controller's reading plus
    // these (found by aligning on the sun or the moon). The session applies
    // them to every reading and every move; the limits stay the controller's
    // own (docs/tracking.md, "Calibration offsets").
    double azOffsetDeg = 0.0; // -180..180
    double elOffsetDeg = 0.0; // -20..20
    RotatorMotion motion;

    // Empty when usable, else why not.
    QString validate() const;

    QJsonObject toJson() const;
    // Reads what toJson() wrote; unknown keys are ignored, missing ones keep
    // their defaults, bad values give an error and no profile.
    static std::optional<RotatorProfile> fromJson(const QJsonObject &json, QString *error);

    // A profile is a few hundred bytes: a file over this is not one.
    static constexpr qint64 kLargestProfile = 1024 * 1024;

    // Atomic save (QSaveFile) and load; errors name the file and the cause.
    // Load reads only a regular file of at most kLargestProfile.
    bool save(const QString &path, QString *error) const;
    static std::optional<RotatorProfile> load(const QString &path, QString *error);
};

} // namespace slew::model
