// SPDX-License-Identifier: GPL-3.0-or-later
#include "rotatormodels.h"

#include <QStringList>

#include <algorithm>

namespace slew::sim {

namespace {

// Figures from the makers' published rotation times, rounded:
// - a Yaesu G-5500 turns 360 degrees of azimuth in about 58 s and 180 degrees
//   of elevation in about 67 s; its AC motors are up to speed in half a second;
// - a SatNOGS-class stepper build is run fast, here at the 30 deg/s speed and
//   acceleration caps of the Easycomm III controller the simulator copies;
// - a heavy-duty rotator for a large dish turns at 1 to 2 deg/s and ramps
//   gently so as not to shake the load.
const std::vector<RotatorModel> kModels = {
    {"g5500", "Yaesu G-5500 class: 6.2 deg/s azimuth, 2.7 deg/s elevation (the default)", 6.2, 2.7, 12.0, 6.0},
    {"satnogs", "fast SatNOGS-class stepper build: 30 deg/s on both axes", 30.0, 30.0, 30.0, 30.0},
    {"heavy", "heavy-duty dish rotator: 2 deg/s azimuth, 1 deg/s elevation", 2.0, 1.0, 2.0, 1.0},
};

// RESET creeps towards the switch at this share of full speed, and never
// faster than 5 deg/s: slow enough to brake before the hard stop.
constexpr double kHomingShare = 0.75;
constexpr double kHomingCap = 5.0;

void applyToAxis(AxisPlant &plant, double speed, double acceleration)
{
    plant.maxSpeed = speed;
    plant.maxAcceleration = acceleration;
    plant.manualSpeed = speed; // ML/MR/MU/MD run at full speed, as a G-5500's buttons do
    plant.homingSpeed = std::min(kHomingCap, kHomingShare * speed);
}

} // namespace

const std::vector<RotatorModel> &rotatorModels()
{
    return kModels;
}

const RotatorModel *findRotatorModel(QStringView name)
{
    for (const RotatorModel &m : kModels) {
        if (name.compare(QLatin1String(m.name), Qt::CaseInsensitive) == 0)
            return &m;
    }
    return nullptr;
}

QString rotatorModelNameList()
{
    QStringList names;
    for (const RotatorModel &m : kModels)
        names << QString::fromLatin1(m.name);
    const QString last = names.takeLast();
    return names.join(QStringLiteral(", ")) + QStringLiteral(" or ") + last;
}

void applyRotatorModel(RotatorConfig &rotator, const RotatorModel &model)
{
    applyToAxis(rotator.azimuth, model.azimuthSpeed, model.azimuthAcceleration);
    applyToAxis(rotator.elevation, model.elevationSpeed, model.elevationAcceleration);
}

} // namespace slew::sim
