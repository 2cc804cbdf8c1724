#pragma once
// What one axis' tuning produced: the two steps, their figures, the fitted
// model and both sets of gains. The wizard charts it, `slew --tune` prints it.

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
    bool applied = false; // the new gains stay on the controller
};

QString axisName(session::Axis axis);  // "az" / "el"
// The gain registers of an axis: CW1..CW3 for azimuth, CW4..CW6 for elevation.
int firstGainRegister(session::Axis axis);

// The before/after table `slew --tune` prints, one header and two rows per result.
QString formatTuningTable(const QList<TuningResult> &results);

} // namespace slew::tuning

Q_DECLARE_METATYPE(slew::tuning::TuningResult)
