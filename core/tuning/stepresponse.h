#pragma once
// One step of one axis as the host saw it: where it started, where it was
// sent, and the positions that came back with the time each arrived. Plain
// values, so the analysis, the model fit, the chart and the table all take
// the same thing.

#include <QList>
#include <QString>

namespace slew::tuning {

struct PositionSample {
    double t = 0.0;        // seconds since the step was commanded
    double position = 0.0; // degrees, as the controller reported it
};

struct StepResponse {
    double start = 0.0;     // degrees, the axis at rest before the step
    double target = 0.0;    // degrees, where it was sent
    double duration = 0.0;  // seconds the step was watched for
    QList<PositionSample> samples;

    double amplitude() const { return target - start; }
    bool isEmpty() const { return samples.isEmpty(); }
};

// The four figures the tuning is judged by.
struct StepMetrics {
    double riseTime = 0.0;         // s, 10 % to 90 % of the step
    double overshootPercent = 0.0; // peak beyond the target, in % of the step
    double settlingTime = 0.0;     // s until the axis stays inside the band
    double steadyStateError = 0.0; // degrees, target minus where it came to rest
    double band = 0.0;             // degrees, the settling band used
    bool rose = false;             // it reached 90 % of the step
    bool settled = false;          // it stayed inside the band before the end
};

// "1.23 s", "—" for figures that were never reached.
QString formatSeconds(double seconds, bool reached);

} // namespace slew::tuning
