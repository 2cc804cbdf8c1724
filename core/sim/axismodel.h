// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One motorised axis: motor and load with inertia and friction, a gearbox
// with optional play, limit switches, hard stops, an encoder, and the servo
// loops of the controller board that drives it.
//
// No I/O and no clock of its own: step(dt) advances it, so a test can run it
// exactly and a server can drive it from wall-clock time.

#include "axisparameters.h"

#include <array>
#include <cstdint>
#include <random>

namespace slew::sim {

enum class DriveMode : std::uint8_t {
    Released, // no drive (SA / SE): a worm gear stops at once, a free drive coasts to rest
    Position, // PID on the encoder reading (AZ / EL / PARK)
    Velocity, // speed loop that also holds its place (VL..VD, VL0 holds)
    Homing,   // RESET: creep towards the lower switch, then zero there
};

// Error bits as GE reports them (SatNOGS numbering). 1 "no error" is added by
// whoever formats the register.
namespace AxisError {
constexpr int Sensor = 2;
constexpr int Homing = 4;
constexpr int Motor = 8;
} // namespace AxisError

// Limit switch bits as IP1 / IP2 report them (Easycomm III derivative).
namespace LimitSwitch {
constexpr int Lower = 1; // CCW for azimuth, down for elevation
constexpr int Upper = 2; // CW for azimuth, up for elevation
} // namespace LimitSwitch

class AxisModel {
public:
    explicit AxisModel(const AxisPlant &plant = {}, const PidGains &gains = {}, std::uint32_t seed = 1);

    // Advances the axis by dt seconds. Call with small steps (1 ms): the
    // integration is explicit.
    void step(double dt);
    // The same, and whether the step left the axis exactly as it was: at a
    // standstill no further step ends, since a step depends on nothing but
    // the axis itself (no noise is drawn then). Whoever runs the physics may
    // skip the steps that would follow until a command.
    bool stepAtStandstill(double dt);

    // Puts the axis at rest at an angle, as if it had been left there.
    void placeAt(double degrees);

    // Commands, in the encoder's frame (what the host reads back).
    void commandPosition(double degrees);
    void commandVelocity(double degreesPerSecond); // sign gives the direction
    void release();
    void home();
    void clearErrors() { m_errors = 0; }

    const AxisPlant &plant() const { return m_plant; }
    void setPlant(const AxisPlant &plant);
    const PidGains &gains() const { return m_gains; }
    void setGains(const PidGains &gains) { m_gains = gains; }
    const AxisFaults &faults() const { return m_faults; }
    void setFaults(const AxisFaults &faults);

    // What the controller knows: the encoder reading and what it derives.
    double position() const { return m_reading; }
    double measuredVelocity() const { return m_measuredVelocity; } // what the loops use
    double reportedVelocity() const { return m_reportedVelocity; } // smoothed for IP7/IP8, \?ENC
    std::int64_t encoderTicks() const { return m_readingTicks; }
    std::int64_t encoderVelocityTicks() const;

    // What the physics knows (tests and the plot of the truth).
    double antennaPosition() const { return m_antenna; }
    double motorPosition() const { return m_motor; }
    double velocity() const { return m_velocity; }
    double acceleration() const { return m_acceleration; }

    DriveMode mode() const { return m_mode; }
    double targetPosition() const { return m_target; }
    double targetVelocity() const { return m_velocityTarget; }
    bool isSettled() const;      // position mode and within tolerance, at rest
    bool isMoving() const;       // anything but settled or at rest
    // What a stop leaves: the drive released (SA / SE), or holding a zero
    // speed (VL0, which Slew sends after SA to brake a free-running drive).
    bool isStopped() const
    {
        return m_mode == DriveMode::Released || (m_mode == DriveMode::Velocity && m_velocityTarget == 0.0);
    }
    int limitSwitches() const;   // LimitSwitch bits
    int errors() const { return m_errors; }
    double load() const;         // drive effort in percent of the torque limit
    double effort() const { return m_effort; }

    static constexpr double settleTolerance = 0.1; // degrees

private:
    // Everything step() may change, to tell a step that changed nothing.
    // A member added to the physics, the loops or the fault detection
    // belongs here too.
    using State = std::array<double, 22>;
    State state() const;
    double sampleEncoder();
    double positionDrive(double dt);
    // A relay controller's drive: full torque towards the target, or none.
    double relayDrive();
    double velocityDrive(double target, double dt);
    double deliveredEffort(double drive) const;
    void integrate(double drive, bool powered, double dt);
    void move(double dt); // motor, gear play and hard stops at the current speed
    void detectFaults(double drive, double previousReading, double dt);
    void fail(int errorBit);

    AxisPlant m_plant;
    PidGains m_gains;
    AxisFaults m_faults;
    std::mt19937 m_rng;

    // Physics.
    double m_motor = 0.0;
    double m_antenna = 0.0;
    double m_velocity = 0.0;
    double m_acceleration = 0.0;

    // Encoder and the controller's view of it.
    double m_encoderOffset = 0.0; // antenna angle that reads as zero
    double m_reading = 0.0;
    std::int64_t m_readingTicks = 0;
    double m_measuredVelocity = 0.0;
    double m_reportedVelocity = 0.0;

    // Servo.
    DriveMode m_mode = DriveMode::Released;
    double m_target = 0.0;
    double m_velocityTarget = 0.0;
    double m_integral = 0.0;      // position loop: degree-seconds of error
    double m_lastError = 0.0;
    double m_holdError = 0.0;     // velocity loop: degrees behind the commanded motion
    double m_effort = 0.0;
    int m_relay = 0;              // relay drive: -1 or +1 while a relay is on, 0 off

    // Fault detection.
    int m_errors = 0;
    double m_stallSeconds = 0.0;
    double m_frozenSeconds = 0.0;
    double m_homingTravel = 0.0;
    bool m_homingBackOff = false; // homing began on the switch and is climbing off it
};

} // namespace slew::sim
