// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The numbers that describe one simulated axis: its mechanics, its servo
// gains and the faults switched on for it. Plain values, so options parsing,
// the rotator and the tests can pass them around freely.

#include <cstdint>

namespace slew::sim {

// What the gearbox does when the motor lets go.
enum class DriveTrain : std::uint8_t {
    SelfLocking, // a worm gear: the load cannot turn the worm, so a released axis stops at once
    FreeRunning, // a spur gear or direct drive: a released axis coasts until friction stops it
};

// How the controller drives the motor towards a position.
enum class MotorControl : std::uint8_t {
    Servo, // a speed loop: the drive follows the position loop's demand smoothly
    Relay, // relays: full power one way or the other, or off (a G-5500's own
           // control box behind a GS-232-style board): on when the axis is
           // further than relayOnDeg from its target, off within relayOffDeg
};

// Mechanics of one axis, in degrees and seconds. The motor torque is written
// as the angular acceleration it gives the load (deg/s^2 for inertia 1), so
// the gains below read as "deg/s^2 of drive per degree of error".
// The speed and acceleration defaults are those of a Yaesu G-5500 class
// azimuth (360 degrees in about 58 s); rotatormodels.h holds the elevation
// figures and the other classes.
struct AxisPlant {
    double minDegrees = 0.0;      // lower (CCW / down) limit switch
    double maxDegrees = 360.0;    // upper (CW / up) limit switch
    double hardStopMargin = 1.0;  // mechanical stop this far beyond each switch
    double inertia = 1.0;         // relative to the nominal load
    double viscousFriction = 0.5; // deg/s^2 of drag per deg/s
    double coulombFriction = 0.2; // deg/s^2, also the breakaway (stiction) level
    double torqueLimit = 40.0;    // deg/s^2, the most the motor can deliver
    double maxSpeed = 6.2;        // deg/s, the driver's cap
    double maxAcceleration = 12.0; // deg/s^2, the driver's ramp
    DriveTrain driveTrain = DriveTrain::SelfLocking;
    // How hard a self-locking gear stops a released axis: only the motor's own
    // rotor still turns, and the worm's friction eats its momentum within a
    // fraction of a worm turn, a few hundredths of a degree at the antenna.
    double lockDeceleration = 1000.0; // deg/s^2
    double ticksPerDegree = 100.0; // encoder resolution, reported by \?ENC
    double homingSpeed = 5.0;     // deg/s while RESET looks for the switch: slow enough to
                                  // brake before the hard stop once it trips
    double manualSpeed = 6.2;     // deg/s for ML/MR/MU/MD (Easycomm II has no speed): full speed
    MotorControl control = MotorControl::Servo;
    double relayOnDeg = 0.5;      // a relay drive starts when the target is further than this
    double relayOffDeg = 0.1;     // and stops within this, or once past the target
};

// Position servo gains, as CW1..CW3 (azimuth) and CW4..CW6 (elevation) set
// them. The defaults settle a 10 degree step in about 2.5 s with hundredths
// of a degree of overshoot, and start braking early enough that a long slew
// at the speed cap does not overshoot either. kp 40 with kd 0 (no damping)
// overshoots a 10 degree step by ~90 %: something for a tuner to fix.
struct PidGains {
    double kp = 40.0; // deg/s^2 per degree of error
    double ki = 2.0;  // deg/s^2 per degree-second
    double kd = 20.0; // deg/s^2 per deg/s (on the measured speed, so a new target gives no kick)
};

// Faults of one axis that a test or an operator switches on and off.
struct AxisFaults {
    bool jam = false;             // the axis is stuck; a motor error follows after stallSeconds
    bool encoderFreeze = false;   // the reading stops changing; a sensor error follows when it moves
    double encoderNoise = 0.0;    // degrees of uniform noise on every reading; large jumps are a sensor error
    bool missingEndStop = false;  // the lower switch never trips: homing fails
    // The motor is wired the wrong way round: driven up (CW) it turns down
    // (CCW), so the position loop runs away from its target.
    bool reversedMotor = false;
    double backlash = 0.0;        // degrees of play between motor and antenna
    double stallSeconds = 1.0;    // how long a driven, unmoving axis takes to become a motor error

    friend bool operator==(const AxisFaults &, const AxisFaults &) = default;
};

} // namespace slew::sim
