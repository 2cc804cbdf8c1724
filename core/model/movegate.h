// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one place that decides whether a move is legal and what is sent for
// it. Every path to the wire asks it: the operator's go-to, jog, presets and
// plot clicks, park, the rotctld server, the tuner's steps, raw lines and
// park registers, through RotatorSession, which refuses before a byte goes
// out. Widgets ask the session for the same decision as a preview.
//
// The limits in force are the profile's, narrowed by any the link reports
// (rotctld's \dump_state): a move must fit both. A bearing (0..360) may be
// reached at +-360 on a rotator with overlap or a south stop; the shortest
// legal move from the current azimuth wins.

#include "rotatorlimits.h"

#include <QString>

#include <limits>
#include <optional>

namespace slew::model {

// What the gate decided: allowed (refusal empty) with the positions to
// command, or refused and why. Axes not asked about stay NaN.
struct MoveCheck {
    QString refusal;
    double azimuth = std::numeric_limits<double>::quiet_NaN();
    double elevation = std::numeric_limits<double>::quiet_NaN();
    bool allowed() const { return refusal.isEmpty(); }
};

class MoveGate {
public:
    MoveGate() = default;
    explicit MoveGate(const RotatorLimits &profile, std::optional<RotatorLimits> reported = std::nullopt);

    void setProfileLimits(const RotatorLimits &limits) { m_profile = limits; }
    void setReportedLimits(std::optional<RotatorLimits> limits) { m_reported = limits; }
    const RotatorLimits &profileLimits() const { return m_profile; }
    const std::optional<RotatorLimits> &reportedLimits() const { return m_reported; }
    // The travel in force: the profile's, narrowed by the reported.
    RotatorLimits limits() const;

    // A bearing (or a mechanical azimuth outside 0..360) and an elevation.
    MoveCheck pointing(double azimuth, double elevation, std::optional<double> currentAzimuth) const;
    // One axis. azimuthBearing chooses among +-360 as pointing() does;
    // azimuthPosition takes the angle as the mechanical position it names
    // (a tuning step, a raw line, a register).
    MoveCheck azimuthBearing(double azimuth, std::optional<double> currentAzimuth) const;
    MoveCheck azimuthPosition(double azimuth) const;
    MoveCheck elevation(double elevation) const;
    // Both axes as mechanical positions (a park position in the controller's
    // registers).
    MoveCheck mechanical(double azimuth, double elevation) const;
    // Driving an axis at a speed: refused at or past the limit it drives
    // towards (at is the axis' position, when known).
    MoveCheck drive(bool azimuthAxis, bool positive, std::optional<double> at) const;

private:
    RotatorLimits m_profile;
    std::optional<RotatorLimits> m_reported;
};

} // namespace slew::model
