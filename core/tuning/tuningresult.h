#pragma once
// What one axis' tuning produced: the two steps, their figures, the fitted
// model and both sets of gains. The wizard charts it, `slew --tune` prints it.

#include "axismotion.h"
#include "axisplantmodel.h"
#include "stepresponse.h"

#include "model/rotatorprofile.h"
#include "session/sessiontypes.h"

#include <QMetaType>
#include <QStringList>

namespace slew::tuning {

struct TuningResult {
    session::Axis axis = session::Axis::Azimuth;
    model::PidGains oldGains;
    model::PidGains newGains;
    StepResponse before;
    StepResponse after;
    StepMetrics beforeMetrics;
    StepMetrics afterMetrics;
    PlantFit fit;
    double dampingBefore = 0.0;
    double dampingAfter = 0.0;
    AxisMotion motion; // speed, acceleration and response delay, from the first step
    bool applied = false; // the new gains stay on the controller
};

QString axisName(session::Axis axis);  // "az" / "el"
// The gain registers of an axis: CW1..CW3 for azimuth, CW4..CW6 for elevation.
int firstGainRegister(session::Axis axis);

// The before/after table `slew --tune` prints, one header and two rows per result.
QString formatTuningTable(const QList<TuningResult> &results);

// The profile's motion with what a tuning run measured on its axis: the
// speed and acceleration of that axis, and its response delay as the
// tracker's lead (the axis tuned last gives it).
model::RotatorMotion withMeasuredMotion(model::RotatorMotion motion, const TuningResult &result);

} // namespace slew::tuning

Q_DECLARE_METATYPE(slew::tuning::TuningResult)
