// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The calibration offsets found for a rotator (sun or moon alignment),
// remembered per link URI in the application's settings, so the window puts
// them back when it connects to the same rotator. A profile file carries its
// own offsets too (RotatorProfile::toJson); this is the window's memory.

#include <QString>

#include <optional>

namespace slew::model {

struct CalibrationOffsets {
    double azDeg = 0.0;
    double elDeg = 0.0;
};

std::optional<CalibrationOffsets> savedCalibration(const QString &uri);
void saveCalibration(const QString &uri, const CalibrationOffsets &offsets);

} // namespace slew::model
