// SPDX-License-Identifier: GPL-3.0-or-later
#include "simulatedrotator.h"

#include "rotatormodels.h"

#include <algorithm>
#include <cmath>

namespace slew::sim {

namespace {

constexpr double kAmbient = 25.0;          // deg C
constexpr double kHeatingPerAxis = 30.0;   // deg C above ambient at full load, steady state
constexpr double kThermalSeconds = 60.0;   // time constant of the motor housing
// Closer than this to where it is heading, the temperature input (two
// decimals) shows no change any more.
constexpr double kSettledTemperature = 0.002;

// CR9 as SatNOGS numbers it (0 position, 1 speed), extended for the two
// modes SatNOGS does not have.
double controlMode(DriveMode mode)
{
    switch (mode) {
    case DriveMode::Position: return 0;
    case DriveMode::Velocity: return 1;
    case DriveMode::Released: return 2;
    case DriveMode::Homing: return 3;
    }
    return 2;
}

} // namespace

RotatorConfig::RotatorConfig()
{
    elevation.maxDegrees = 180.0;
    applyRotatorModel(*this, rotatorModels().front());
}

SimulatedRotator::SimulatedRotator(const RotatorConfig &config)
    : m_config(config),
      m_azimuth(config.azimuth, config.azimuthGains, config.seed),
      m_elevation(config.elevation, config.elevationGains, config.seed * 2654435761u + 1u),
      m_temperature(kAmbient)
{
    m_azimuth.placeAt(config.startAzimuth);
    m_elevation.placeAt(config.startElevation);
    m_commandedAzimuth = config.startAzimuth;
    m_commandedElevation = config.startElevation;
}

void SimulatedRotator::advanceTo(double t)
{
    m_requestedTime = std::max(m_requestedTime, t);
    // Compare in whole steps so that rounding never loses or adds one.
    const auto target = static_cast<long long>(std::floor(m_requestedTime / stepSeconds + 1e-6));
    auto done = static_cast<long long>(std::llround(m_time / stepSeconds));
    while (done < target) {
        m_standstill = step(stepSeconds);
        ++done;
        if (m_standstill && done < target) {
            // Every step to come would repeat this one exactly, but for the
            // temperature, which goes on towards where the load holds it:
            // the same steps' cooling in closed form.
            const double left = double(target - done);
            m_temperature = steadyTemperature()
                + (m_temperature - steadyTemperature()) * std::pow(1.0 - stepSeconds / kThermalSeconds, left);
            done = target;
        }
    }
    m_time = double(done) * stepSeconds;
}

bool SimulatedRotator::atRest() const
{
    return m_standstill && std::abs(m_temperature - steadyTemperature()) < kSettledTemperature;
}

double SimulatedRotator::steadyTemperature() const
{
    const double loadA = m_azimuth.load() / 100.0;
    const double loadE = m_elevation.load() / 100.0;
    return kAmbient + kHeatingPerAxis * (loadA * loadA + loadE * loadE);
}

bool SimulatedRotator::step(double dt)
{
    const bool azimuthStill = m_azimuth.stepAtStandstill(dt);
    const bool elevationStill = m_elevation.stepAtStandstill(dt);
    m_temperature += (steadyTemperature() - m_temperature) * dt / kThermalSeconds;
    return azimuthStill && elevationStill;
}

double SimulatedRotator::resolveAzimuth(double degrees) const
{
    const AxisPlant &p = m_azimuth.plant();
    // Above 360 a command is an explicit mechanical angle; below, a bearing
    // that the overlap may offer twice.
    if (degrees > 360.0)
        return degrees;
    const double here = m_azimuth.position();
    double best = degrees;
    for (double candidate : {degrees + 360.0, degrees - 360.0}) {
        if (candidate >= p.minDegrees && candidate <= p.maxDegrees
            && std::fabs(candidate - here) < std::fabs(best - here))
            best = candidate;
    }
    return best;
}

bool SimulatedRotator::pointAzimuth(double degrees)
{
    commanded();
    const AxisPlant &p = m_azimuth.plant();
    if (!std::isfinite(degrees) || degrees < p.minDegrees || degrees > p.maxDegrees)
        return false;
    m_commandedAzimuth = degrees;
    m_azimuth.commandPosition(resolveAzimuth(degrees));
    return true;
}

bool SimulatedRotator::pointElevation(double degrees)
{
    commanded();
    const AxisPlant &p = m_elevation.plant();
    if (!std::isfinite(degrees) || degrees < p.minDegrees || degrees > p.maxDegrees)
        return false;
    m_commandedElevation = degrees;
    m_elevation.commandPosition(degrees);
    return true;
}

void SimulatedRotator::driveAzimuth(double millidegreesPerSecond)
{
    commanded();
    m_commandedAzimuthSpeed = millidegreesPerSecond;
    m_azimuth.commandVelocity(millidegreesPerSecond / 1000.0);
}

void SimulatedRotator::driveElevation(double millidegreesPerSecond)
{
    commanded();
    m_commandedElevationSpeed = millidegreesPerSecond;
    m_elevation.commandVelocity(millidegreesPerSecond / 1000.0);
}

void SimulatedRotator::park()
{
    pointAzimuth(m_config.parkAzimuth);
    pointElevation(m_config.parkElevation);
}

void SimulatedRotator::reset()
{
    commanded();
    m_azimuth.home();
    m_elevation.home();
    m_commandedAzimuth = m_azimuth.plant().minDegrees;
    m_commandedElevation = m_elevation.plant().minDegrees;
    m_commandedAzimuthSpeed = m_commandedElevationSpeed = 0.0;
}

std::optional<double> SimulatedRotator::readRegister(int index) const
{
    const PidGains &a = m_azimuth.gains();
    const PidGains &e = m_elevation.gains();
    switch (index) {
    case 1: return a.kp;
    case 2: return a.ki;
    case 3: return a.kd;
    case 4: return e.kp;
    case 5: return e.ki;
    case 6: return e.kd;
    case 7: return m_config.parkAzimuth;
    case 8: return m_config.parkElevation;
    case 9: return controlMode(m_azimuth.mode());
    case 10: return m_commandedAzimuth;
    case 11: return m_commandedElevation;
    case 12: return m_commandedAzimuthSpeed;
    case 13: return m_commandedElevationSpeed;
    default: return std::nullopt;
    }
}

bool SimulatedRotator::writeRegister(int index, double value)
{
    commanded();
    if (!std::isfinite(value))
        return false;
    auto setGain = [&](AxisModel &axis, double PidGains::*gain) {
        if (value < 0.0 || value > 10000.0)
            return false;
        PidGains g = axis.gains();
        g.*gain = value;
        axis.setGains(g);
        return true;
    };
    switch (index) {
    case 1: return setGain(m_azimuth, &PidGains::kp);
    case 2: return setGain(m_azimuth, &PidGains::ki);
    case 3: return setGain(m_azimuth, &PidGains::kd);
    case 4: return setGain(m_elevation, &PidGains::kp);
    case 5: return setGain(m_elevation, &PidGains::ki);
    case 6: return setGain(m_elevation, &PidGains::kd);
    case 7:
        if (value < m_azimuth.plant().minDegrees || value > m_azimuth.plant().maxDegrees)
            return false;
        m_config.parkAzimuth = value;
        return true;
    case 8:
        if (value < m_elevation.plant().minDegrees || value > m_elevation.plant().maxDegrees)
            return false;
        m_config.parkElevation = value;
        return true;
    default: return false;
    }
}

std::optional<double> SimulatedRotator::readInput(int index) const
{
    switch (index) {
    case 0: return m_temperature;
    case 1: return double(m_azimuth.limitSwitches());
    case 2: return double(m_elevation.limitSwitches());
    case 3: return m_azimuth.position();
    case 4: return m_elevation.position();
    case 5: return std::round(m_azimuth.load());
    case 6: return std::round(m_elevation.load());
    case 7: return m_azimuth.reportedVelocity();
    case 8: return m_elevation.reportedVelocity();
    default: return std::nullopt;
    }
}

int SimulatedRotator::axisStatus(Axis which) const
{
    const AxisModel &a = axis(which);
    if (a.errors() != 0)
        return AxisStatus::Error;
    switch (a.mode()) {
    case DriveMode::Released: return AxisStatus::Idle;
    case DriveMode::Velocity:
        // A zero speed command holds the axis where it is (Slew's Stop on a
        // free-running drive): at rest, that is not moving.
        return a.targetVelocity() == 0.0 && !a.isMoving() ? AxisStatus::Idle : AxisStatus::Moving;
    case DriveMode::Homing: return AxisStatus::Moving;
    case DriveMode::Position:
        return a.isSettled() ? AxisStatus::Pointing : AxisStatus::Pointing | AxisStatus::Moving;
    }
    return AxisStatus::Idle;
}

int SimulatedRotator::status() const
{
    return axisStatus(Axis::Azimuth) | (axisStatus(Axis::Elevation) << 8);
}

int SimulatedRotator::combinedStatus() const
{
    const int a = axisStatus(Axis::Azimuth);
    const int e = axisStatus(Axis::Elevation);
    if ((a | e) & AxisStatus::Error)
        return AxisStatus::Error;
    if ((a | e) & AxisStatus::Moving)
        return AxisStatus::Moving;
    if ((a | e) & AxisStatus::Pointing)
        return AxisStatus::Pointing;
    return AxisStatus::Idle;
}

int SimulatedRotator::errorRegister() const
{
    const int bits = m_azimuth.errors() | m_elevation.errors();
    return bits == 0 ? 1 : bits;
}

std::array<std::int64_t, 4> SimulatedRotator::encoders() const
{
    return {m_azimuth.encoderTicks(), m_elevation.encoderTicks(), m_azimuth.encoderVelocityTicks(),
            m_elevation.encoderVelocityTicks()};
}

} // namespace slew::sim
