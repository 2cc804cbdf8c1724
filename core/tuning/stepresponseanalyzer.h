#pragma once
// Reads rise time, overshoot, settling time and steady-state error off a
// recorded step. Samples arrive unevenly (a poll, or a push when the value
// changed), so between two samples the axis is taken to have held the
// earlier value: that is what the controller last said.

#include "stepresponse.h"

namespace slew::tuning {

struct AnalysisSettings {
    double bandPercent = 2.0;   // settling band, % of the step
    double minimumBand = 0.05;  // degrees: never finer than a few encoder counts
    double tailSeconds = 0.5;   // the steady state is the mean over this last stretch
};

class StepResponseAnalyzer {
public:
    explicit StepResponseAnalyzer(const AnalysisSettings &settings = {}) : m_settings(settings) {}

    // The band a step of this size is judged against.
    double bandFor(double amplitude) const;

    StepMetrics analyze(const StepResponse &step) const;

private:
    AnalysisSettings m_settings;
};

} // namespace slew::tuning
