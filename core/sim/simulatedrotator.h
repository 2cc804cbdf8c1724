// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The simulated az/el rotator: two axes, the controller board's registers
// (CR1..CR13), its inputs (IP0..IP8), status and error registers, a motor
// temperature, and the Easycomm-level commands (point, drive, stop, park,
// reset). No I/O and no wall clock: advanceTo() runs the physics in fixed
// 1 ms steps, so a test can advance it exactly. Once both axes stand still
// (a step changes nothing), the steps up to the time asked for are not run
// one by one: only the motors' cooling goes on, worked out at once. A
// station left alone for a day catches up in no time.

#include "axismodel.h"

#include <QByteArray>

#include <array>
#include <cstdint>
#include <optional>

namespace slew::sim {

enum class Axis : std::uint8_t { Azimuth, Elevation };

struct RotatorConfig {
    AxisPlant azimuth;   // maxDegrees 360..450: above 360 is the overlap
    AxisPlant elevation; // maxDegrees 90 or 180
    PidGains azimuthGains;
    PidGains elevationGains;
    double parkAzimuth = 0.0;   // CW7
    double parkElevation = 0.0; // CW8
    double startAzimuth = 0.0;
    double startElevation = 0.0;
    QByteArray version = "SlewSim-1.0";
    std::uint32_t seed = 1;

    RotatorConfig();
};

// Status bits of one axis (Easycomm III derivative's GS, one byte per axis).
namespace AxisStatus {
constexpr int Idle = 1;
constexpr int Moving = 2;
constexpr int Pointing = 4;
constexpr int Error = 8;
} // namespace AxisStatus

class SimulatedRotator {
public:
    static constexpr double stepSeconds = 0.001; // the physics runs at 1 kHz

    explicit SimulatedRotator(const RotatorConfig &config = {});

    // Runs the physics up to simulated time t (seconds since start) in
    // stepSeconds steps; a remainder waits for the next call.
    void advanceTo(double t);
    void advanceBy(double seconds) { advanceTo(m_requestedTime + seconds); }
    double time() const { return m_time; }
    // Both axes were at a standstill when last advanced: only the motors'
    // temperature may still change until a command.
    bool standingStill() const { return m_standstill; }
    // Nothing left to happen until a command: standing still, and the
    // motors as cool as the present load keeps them (to the hundredth of a
    // degree the temperature input reports).
    bool atRest() const;

    // Commands. Angles outside the limits are refused (false) and move nothing.
    bool pointAzimuth(double degrees);
    bool pointElevation(double degrees);
    void driveAzimuth(double millidegreesPerSecond);   // positive is right (CW)
    void driveElevation(double millidegreesPerSecond); // positive is up
    void stopAzimuth()
    {
        commanded();
        m_azimuth.release();
    }
    void stopElevation()
    {
        commanded();
        m_elevation.release();
    }
    void park();
    void reset(); // homes both axes against their lower switches

    // Registers as CR / CW see them: 1..3 az PID, 4..6 el PID, 7/8 park,
    // 9 control mode (read only), 10..13 commanded values (read only).
    std::optional<double> readRegister(int index) const;
    bool writeRegister(int index, double value);
    // Inputs as IP reports them; nullopt for an input that does not exist.
    std::optional<double> readInput(int index) const;

    int axisStatus(Axis axis) const;   // AxisStatus bits of one axis
    int status() const;                // the Easycomm III derivative: azimuth | elevation << 8
    int combinedStatus() const;        // SatNOGS: one set of bits for the whole rotator
    int errorRegister() const;         // GE: 1 when clear, else the error bits
    std::array<std::int64_t, 4> encoders() const; // \?ENC: az, el ticks; az, el ticks/s
    double temperature() const { return m_temperature; }
    const QByteArray &version() const { return m_config.version; }

    AxisModel &axis(Axis a) { return a == Axis::Azimuth ? m_azimuth : m_elevation; }
    const AxisModel &axis(Axis a) const { return a == Axis::Azimuth ? m_azimuth : m_elevation; }
    void setFaults(Axis a, const AxisFaults &faults)
    {
        commanded();
        axis(a).setFaults(faults);
    }
    const RotatorConfig &config() const { return m_config; }

    // Where an azimuth command will really go: in the overlap, the one of the
    // two mechanical angles for the bearing that is nearer (Micro-2g program).
    double resolveAzimuth(double degrees) const;

private:
    // One step of both axes; true when neither changed (AxisModel::stepAtStandstill).
    bool step(double dt);
    double steadyTemperature() const;
    // Any command may set an axis moving: a standstill is for the physics to find again.
    void commanded() { m_standstill = false; }

    RotatorConfig m_config;
    AxisModel m_azimuth;
    AxisModel m_elevation;
    double m_time = 0.0;
    double m_requestedTime = 0.0;
    bool m_standstill = false; // the last step run changed neither axis
    double m_temperature = 25.0;
    double m_commandedAzimuth = 0.0;
    double m_commandedElevation = 0.0;
    double m_commandedAzimuthSpeed = 0.0;   // mdeg/s
    double m_commandedElevationSpeed = 0.0; // mdeg/s
};

} // namespace slew::sim
