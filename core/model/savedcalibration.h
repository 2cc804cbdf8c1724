// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The calibration offsets found for a rotator (sun or moon alignment),
// remembered per link URI in the application's settings, so the window puts
// them back when it connects to the same rotator. A profile file carries its
// own offsets too (RotatorProfile::toJson); this is the window's memory.
//
// Each rotor of a multi-rotor controller (a Micro-2g's four on one line) is
// its own rotator, named by the URI's `rotor` item: its offsets are its own.
// The key puts that item last, so `…?rotor=3&baud=9600` and
// `…?baud=9600&rotor=3` are the same rotor.

#include <QString>

#include <optional>

namespace slew::model {

struct CalibrationOffsets {
    double azDeg = 0.0;
    double elDeg = 0.0;
};

// The settings key's URI: as given, with a `rotor` item moved to the end.
QString calibrationUri(const QString &uri);

std::optional<CalibrationOffsets> savedCalibration(const QString &uri);
void saveCalibration(const QString &uri, const CalibrationOffsets &offsets);

} // namespace slew::model
