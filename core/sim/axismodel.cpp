// SPDX-License-Identifier: GPL-3.0-or-later
#include "axismodel.h"

#include <algorithm>
#include <cmath>

namespace slew::sim {

namespace {

// The speed loop used by VL..VD and by homing: a stiff PI on speed whose
// integral is the distance lagging behind the commanded motion, so a zero
// speed command holds its place against a push (VL0 in the Easycomm III derivative).
constexpr double kVelocityGain = 10.0;    // deg/s^2 per deg/s
constexpr double kHoldStiffness = 40.0;   // deg/s^2 per degree behind
constexpr double kVelocityFilter = 0.02;  // s, smoothing of the encoder's derivative
constexpr double kReportFilter = 0.1;     // s, further smoothing for IP7/IP8 and \?ENC
constexpr double kStallSpeed = 0.1;       // deg/s: slower than this while pushing is a stall
constexpr double kStallEffort = 0.5;      // share of the torque limit that counts as pushing
constexpr double kFrozenSpeed = 1.0;      // deg/s: moving this fast must change the reading
constexpr double kFrozenSeconds = 0.5;
constexpr double kIntegralZone = 2.0;     // degrees from the target where the I term works
constexpr double kHomeClearance = 0.1;    // degrees between the lower switch edge and zero
constexpr double kHomeBackOff = 1.0;      // degrees above the switch edge before homing turns back
constexpr double kRestSpeed = 1e-4;       // deg/s, below which friction holds the axis

double sign(double v)
{
    return v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0);
}

} // namespace

AxisModel::AxisModel(const AxisPlant &plant, const PidGains &gains, std::uint32_t seed)
    : m_plant(plant), m_gains(gains), m_rng(seed)
{
    m_reading = sampleEncoder();
    m_target = m_reading;
}

void AxisModel::setPlant(const AxisPlant &plant)
{
    m_plant = plant;
    m_reading = sampleEncoder();
}

void AxisModel::setFaults(const AxisFaults &faults)
{
    m_faults = faults;
    m_stallSeconds = 0.0;
    m_frozenSeconds = 0.0;
}

void AxisModel::placeAt(double degrees)
{
    m_motor = m_antenna = degrees + m_encoderOffset;
    m_velocity = m_acceleration = m_measuredVelocity = m_reportedVelocity = 0.0;
    m_reading = sampleEncoder();
    m_target = m_reading;
}

void AxisModel::commandPosition(double degrees)
{
    if (m_mode != DriveMode::Position)
        m_integral = 0.0;
    m_mode = DriveMode::Position;
    m_target = degrees;
}

void AxisModel::commandVelocity(double degreesPerSecond)
{
    if (m_mode != DriveMode::Velocity)
        m_holdError = 0.0;
    m_mode = DriveMode::Velocity;
    m_velocityTarget = std::clamp(degreesPerSecond, -m_plant.maxSpeed, m_plant.maxSpeed);
}

void AxisModel::release()
{
    m_mode = DriveMode::Released;
    m_velocityTarget = 0.0;
}

void AxisModel::home()
{
    // RESET starts from a clean slate: a failed homing can be retried.
    m_errors = 0;
    m_mode = DriveMode::Homing;
    m_holdError = 0.0;
    m_homingTravel = 0.0;
    // Already on the switch (a homing cut short, a jog into it): the edge
    // can only be found from above, so the axis first climbs off it.
    m_homingBackOff = (limitSwitches() & LimitSwitch::Lower) != 0;
    m_stallSeconds = 0.0;
    m_frozenSeconds = 0.0;
}

std::int64_t AxisModel::encoderVelocityTicks() const
{
    return std::llround(m_reportedVelocity * m_plant.ticksPerDegree);
}

bool AxisModel::isSettled() const
{
    return m_mode == DriveMode::Position && std::fabs(m_target - m_reading) <= settleTolerance
        && std::fabs(m_measuredVelocity) < 0.5;
}

bool AxisModel::isMoving() const
{
    if (m_mode == DriveMode::Position)
        return !isSettled();
    return std::fabs(m_velocity) > 0.01 || m_mode == DriveMode::Homing;
}

int AxisModel::limitSwitches() const
{
    int bits = 0;
    if (!m_faults.missingEndStop && m_antenna <= m_plant.minDegrees)
        bits |= LimitSwitch::Lower;
    if (m_antenna >= m_plant.maxDegrees)
        bits |= LimitSwitch::Upper;
    return bits;
}

double AxisModel::load() const
{
    return 100.0 * std::fabs(m_effort) / m_plant.torqueLimit;
}

double AxisModel::sampleEncoder()
{
    double raw = m_antenna - m_encoderOffset;
    if (m_faults.encoderNoise > 0.0) {
        std::uniform_real_distribution<double> noise(-m_faults.encoderNoise, m_faults.encoderNoise);
        raw += noise(m_rng);
    }
    m_readingTicks = std::llround(raw * m_plant.ticksPerDegree);
    return double(m_readingTicks) / m_plant.ticksPerDegree;
}

void AxisModel::step(double dt)
{
    if (dt <= 0.0)
        return;

    const double previousReading = m_reading;
    if (!m_faults.encoderFreeze)
        m_reading = sampleEncoder();
    m_measuredVelocity += (dt / kVelocityFilter) * ((m_reading - previousReading) / dt - m_measuredVelocity);
    m_reportedVelocity += (dt / kReportFilter) * (m_measuredVelocity - m_reportedVelocity);

    double drive = 0.0;
    if (m_errors == 0) {
        switch (m_mode) {
        case DriveMode::Released: break;
        case DriveMode::Position:
            drive = m_plant.control == MotorControl::Relay ? relayDrive() : positionDrive(dt);
            break;
        case DriveMode::Velocity: drive = velocityDrive(m_velocityTarget, dt); break;
        case DriveMode::Homing:
            drive = velocityDrive(m_homingBackOff ? m_plant.homingSpeed : -m_plant.homingSpeed, dt);
            break;
        }
    }

    // The limit switches are wired into the driver: it will not push further
    // into a switch that has tripped, whatever the loop asks for.
    bool powered = m_errors == 0 && m_mode != DriveMode::Released;
    // A relay that is off leaves the motor unpowered: a worm gear stops.
    if (m_mode == DriveMode::Position && m_plant.control == MotorControl::Relay && m_relay == 0)
        powered = false;
    const int switches = limitSwitches();
    if ((switches & LimitSwitch::Lower) && drive < 0.0) {
        drive = 0.0;
        powered = false;
    }
    if ((switches & LimitSwitch::Upper) && drive > 0.0) {
        drive = 0.0;
        powered = false;
    }
    m_effort = drive;

    detectFaults(drive, previousReading, dt);
    if (m_errors != 0)
        powered = false; // a fault found this step cut the drive too
    // A motor wired the wrong way round turns against whatever the board
    // asks of it; the board's own checks above still see what it asked.
    integrate(m_faults.reversedMotor ? -drive : drive, powered, dt);
    if (!powered)
        m_effort = 0.0;
    else if (!m_faults.jam)
        m_effort = deliveredEffort(drive);

    if (m_mode == DriveMode::Homing && m_errors == 0) {
        m_homingTravel += std::fabs(m_velocity) * dt;
        // The switch cuts the motor. A worm gear stops the axis on it at once,
        // and home is where it stopped; a free drive would coast on, so its
        // loop takes over as soon as the switch trips.
        const bool stoppedOnSwitch = m_plant.driveTrain == DriveTrain::FreeRunning || m_velocity == 0.0;
        if (m_homingBackOff) {
            if (m_antenna > m_plant.minDegrees + kHomeBackOff) {
                m_homingBackOff = false; // clear of the switch: now find its edge from above
                m_holdError = 0.0;
            }
        } else if ((limitSwitches() & LimitSwitch::Lower) && stoppedOnSwitch) {
            // Found home. The controller latched the count at the switch
            // edge (minDegrees), not where the axis came to rest past it:
            // the edge reads a little below the minimum, so that the
            // minimum itself lies clear of the switch and the loop can hold
            // it without pushing into a switch that cuts it, however far
            // the axis ran on after the switch tripped.
            m_encoderOffset = m_plant.minDegrees - (m_plant.minDegrees - kHomeClearance);
            m_reading = sampleEncoder();
            m_measuredVelocity = m_velocity;
            commandPosition(m_plant.minDegrees);
        } else if (m_homingTravel > (m_plant.maxDegrees - m_plant.minDegrees) + 2 * m_plant.hardStopMargin + 10.0) {
            fail(AxisError::Homing);
        }
    }
}

AxisModel::State AxisModel::state() const
{
    return {m_motor, m_antenna, m_velocity, m_acceleration, m_encoderOffset, m_reading, double(m_readingTicks),
            m_measuredVelocity, m_reportedVelocity, double(m_mode), m_target, m_velocityTarget, m_integral,
            m_lastError, m_holdError, m_effort, double(m_relay), double(m_errors), m_stallSeconds, m_frozenSeconds,
            m_homingTravel, double(m_homingBackOff)};
}

bool AxisModel::stepAtStandstill(double dt)
{
    // Only an axis that is not moving at all, with its speed filters run
    // down to nothing, can be at a standstill: the comparison is not worth
    // making before. Noise draws from the generator at every step, so a
    // noisy encoder never is.
    if (m_velocity != 0.0 || m_measuredVelocity != 0.0 || m_reportedVelocity != 0.0 || m_faults.encoderNoise > 0.0) {
        step(dt);
        return false;
    }
    const State before = state();
    step(dt);
    return state() == before;
}

double AxisModel::deliveredEffort(double drive) const
{
    // At the driver's speed cap or on its ramp, the loop may ask for full
    // torque, but the driver only lets through what holds the speed or the
    // ramp: friction at cruise, a little more while it speeds up. That is
    // the motor's load (IP5/IP6) and what warms it, not the loop's demand.
    const bool capped = std::fabs(m_velocity) >= m_plant.maxSpeed - 1e-9
        || std::fabs(m_acceleration) >= m_plant.maxAcceleration - 1e-6;
    if (!capped)
        return drive;
    const double needed = m_plant.inertia * m_acceleration + m_plant.viscousFriction * m_velocity
        + m_plant.coulombFriction * sign(m_velocity);
    if (sign(needed) != sign(drive))
        return drive;
    return sign(drive) * std::min(std::fabs(drive), std::fabs(needed));
}

double AxisModel::positionDrive(double dt)
{
    const double error = m_target - m_reading;
    const double unclamped = m_gains.kp * error + m_gains.ki * m_integral - m_gains.kd * m_measuredVelocity;
    const double drive = std::clamp(unclamped, -m_plant.torqueLimit, m_plant.torqueLimit);
    // Anti-windup: the integral is for the last stretch (friction, a steady
    // push), so it only runs near the target and while the output is not
    // saturated; and it never stores more than the motor could deliver.
    // Integrating during the braking of a long move would leave a charge
    // that holds the axis off target against its own friction.
    // Crossing the target empties it: what was stored to get here would
    // only push the axis on past it.
    if (sign(error) != sign(m_lastError))
        m_integral = 0.0;
    m_lastError = error;
    if (drive == unclamped && std::fabs(error) < kIntegralZone)
        m_integral += error * dt;
    if (m_gains.ki > 0.0) {
        const double cap = m_plant.torqueLimit / m_gains.ki;
        m_integral = std::clamp(m_integral, -cap, cap);
    } else {
        m_integral = 0.0;
    }
    return drive;
}

double AxisModel::relayDrive()
{
    const double error = m_target - m_reading;
    if (m_relay == 0 && std::fabs(error) > m_plant.relayOnDeg)
        m_relay = error > 0 ? 1 : -1;
    // Off within the band, or once past the target (the motor does not
    // reverse on the same relay).
    else if (m_relay != 0 && (std::fabs(error) < m_plant.relayOffDeg || (error > 0 ? 1 : -1) != m_relay))
        m_relay = 0;
    return m_relay * m_plant.torqueLimit;
}

double AxisModel::velocityDrive(double target, double dt)
{
    m_holdError += (target - m_measuredVelocity) * dt;
    const double holdCap = m_plant.torqueLimit / kHoldStiffness;
    m_holdError = std::clamp(m_holdError, -holdCap, holdCap);
    // Feed forward the friction the commanded speed will meet, so the loop
    // only corrects the difference.
    const double feedForward = m_plant.viscousFriction * target + m_plant.coulombFriction * sign(target);
    const double drive = feedForward + kVelocityGain * (target - m_measuredVelocity) + kHoldStiffness * m_holdError;
    return std::clamp(drive, -m_plant.torqueLimit, m_plant.torqueLimit);
}

void AxisModel::integrate(double drive, bool powered, double dt)
{
    const double before = m_velocity;
    if (m_faults.jam) {
        m_velocity = 0.0;
        m_acceleration = 0.0;
        return;
    }

    if (!powered && m_plant.driveTrain == DriveTrain::SelfLocking) {
        // The load cannot turn a worm: with the motor let go, only the
        // rotor's own momentum remains, and the worm's friction stops it.
        const double slowed = std::max(0.0, std::fabs(m_velocity) - m_plant.lockDeceleration * dt);
        m_velocity = sign(m_velocity) * slowed;
        move(dt);
        m_acceleration = (m_velocity - before) / dt;
        return;
    }

    double accel = 0.0;
    if (std::fabs(m_velocity) > kRestSpeed) {
        accel = (drive - m_plant.viscousFriction * m_velocity - m_plant.coulombFriction * sign(m_velocity))
            / m_plant.inertia;
    } else if (std::fabs(drive) > m_plant.coulombFriction) {
        accel = (drive - m_plant.coulombFriction * sign(drive)) / m_plant.inertia;
    } else {
        m_velocity = 0.0; // static friction holds it
    }
    accel = std::clamp(accel, -m_plant.maxAcceleration, m_plant.maxAcceleration);

    double velocity = m_velocity + accel * dt;
    // Friction brings a coasting axis to rest; it never drives it backwards.
    if (sign(velocity) != sign(m_velocity) && m_velocity != 0.0 && std::fabs(drive) <= m_plant.coulombFriction)
        velocity = 0.0;
    velocity = std::clamp(velocity, -m_plant.maxSpeed, m_plant.maxSpeed);
    m_velocity = velocity;
    move(dt);
    m_acceleration = (m_velocity - before) / dt;
}

void AxisModel::move(double dt)
{
    m_motor += m_velocity * dt;

    // Gear play: the antenna follows the motor only once the slack is taken up.
    const double halfPlay = m_faults.backlash / 2.0;
    if (m_motor - m_antenna > halfPlay)
        m_antenna = m_motor - halfPlay;
    else if (m_antenna - m_motor > halfPlay)
        m_antenna = m_motor + halfPlay;

    // The hard stops: nothing passes them.
    const double low = m_plant.minDegrees - m_plant.hardStopMargin;
    const double high = m_plant.maxDegrees + m_plant.hardStopMargin;
    if (m_antenna < low || m_antenna > high) {
        const double stop = m_antenna < low ? low : high;
        m_motor += stop - m_antenna;
        m_antenna = stop;
        m_velocity = 0.0;
    }
}

void AxisModel::detectFaults(double drive, double previousReading, double dt)
{
    if (m_errors != 0)
        return;

    // A reading that jumps further than the axis can move is a broken sensor.
    const double plausibleStep = 2.0 * m_plant.maxSpeed * dt + 3.0 / m_plant.ticksPerDegree;
    if (std::fabs(m_reading - previousReading) > plausibleStep) {
        fail(AxisError::Sensor);
        return;
    }

    // The motor turns (back-EMF says so) but the reading stands still.
    if (std::fabs(m_velocity) > kFrozenSpeed && m_reading == previousReading) {
        m_frozenSeconds += dt;
        // A coarse encoder changes rarely at low speed; give it three ticks' time.
        const double limit = std::max(kFrozenSeconds, 3.0 / (m_plant.ticksPerDegree * kFrozenSpeed));
        if (m_frozenSeconds >= limit) {
            fail(AxisError::Sensor);
            return;
        }
    } else if (m_reading != previousReading) {
        m_frozenSeconds = 0.0;
    }

    // Pushing hard without moving: jammed, or homing against a hard stop
    // because the switch never tripped.
    const bool pushing = std::fabs(drive) >= kStallEffort * m_plant.torqueLimit;
    if (pushing && std::fabs(m_velocity) < kStallSpeed) {
        m_stallSeconds += dt;
        if (m_stallSeconds >= m_faults.stallSeconds)
            fail(m_mode == DriveMode::Homing ? AxisError::Homing : AxisError::Motor);
    } else {
        m_stallSeconds = 0.0;
    }
}

void AxisModel::fail(int errorBit)
{
    // The board cuts the drive on any error; RESET clears it.
    m_errors |= errorBit;
    m_mode = DriveMode::Released;
    m_velocityTarget = 0.0;
    m_effort = 0.0;
    m_stallSeconds = 0.0;
    m_frozenSeconds = 0.0;
}

} // namespace slew::sim
