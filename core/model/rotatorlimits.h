#pragma once
// The travel a rotator allows, and the two checks MoveGate (movegate.h) is
// built from. Everything else asks the gate, which also knows the limits a
// link reports. Azimuth may reach past 360° (a Yaesu-style 450° overlap, the Micro-2g program):
// then one bearing has two legal positions and the shortest move is chosen.

#include <QString>

#include <optional>

namespace slew::model {

struct RotatorLimits {
    double azMin = 0.0;
    double azMax = 360.0; // up to 450 with overlap
    double elMin = 0.0;
    double elMax = 90.0;  // 90 or 180

    bool hasOverlap() const { return azMax > 360.0; }
    // Empty when the limits make sense, else why not.
    QString validate() const;

    friend bool operator==(const RotatorLimits &, const RotatorLimits &) = default;
};

struct AzimuthChoice {
    std::optional<double> azimuth; // the position to command
    QString error;                 // why there is none
};

// Picks the position for bearing `target`. A bearing of 0..360 has the
// candidates target, target+360 and target-360 (overlap, south stop); the one
// inside the limits that is the shortest move from `current` wins (the base
// range when `current` is unknown). Any other angle is taken as it is.
AzimuthChoice chooseAzimuth(const RotatorLimits &limits, double target, std::optional<double> current);

// Empty when `el` is inside the limits, else a message that says so.
QString checkElevation(const RotatorLimits &limits, double el);

} // namespace slew::model
