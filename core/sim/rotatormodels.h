// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Named classes of rotator the simulator can stand in for (`model=` in a
// sim: URI, `--model` for slew-sim), so a test, a tuning run or a tracking
// figure can say which kind of rotator it ran on. A preset sets speeds,
// ramps and the drive train of both axes; the other options still apply on
// top of it.

#include "simulatedrotator.h"

#include <QString>
#include <QStringView>

#include <vector>

namespace slew::sim {

struct RotatorModel {
    const char *name;
    const char *description;
    double azimuthSpeed;        // deg/s
    double elevationSpeed;      // deg/s
    double azimuthAcceleration; // deg/s^2
    double elevationAcceleration;
};

// Every preset, the default (g5500) first.
const std::vector<RotatorModel> &rotatorModels();

// The preset of that name (case-insensitive), or nullptr.
const RotatorModel *findRotatorModel(QStringView name);

// "g5500, satnogs or heavy", for help texts and errors.
QString rotatorModelNameList();

// Sets both axes of a rotator to a preset: speed and acceleration caps, and
// the jog and homing speeds that follow from them. The drive train stays as
// it is (every preset is a worm gear; `drive=free` is separate).
void applyRotatorModel(RotatorConfig &rotator, const RotatorModel &model);

} // namespace slew::sim
