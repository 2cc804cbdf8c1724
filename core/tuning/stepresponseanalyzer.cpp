#include "stepresponseanalyzer.h"

#include <algorithm>
#include <cmath>

namespace slew::tuning {

double StepResponseAnalyzer::bandFor(double amplitude) const
{
    return std::max(m_settings.minimumBand, std::fabs(amplitude) * m_settings.bandPercent / 100.0);
}

StepMetrics StepResponseAnalyzer::analyze(const StepResponse &step) const
{
    StepMetrics m;
    const double amplitude = step.amplitude();
    m.band = bandFor(amplitude);
    if (step.samples.isEmpty() || amplitude == 0.0)
        return m;

    // Progress along the step, 0 at the start and 1 at the target, so that
    // steps down read the same as steps up.
    auto progress = [&](double position) { return (position - step.start) / amplitude; };

    double t10 = -1.0;
    double t90 = -1.0;
    double peak = 0.0;
    for (const PositionSample &s : step.samples) {
        const double p = progress(s.position);
        if (t10 < 0.0 && p >= 0.1)
            t10 = s.t;
        if (t90 < 0.0 && p >= 0.9)
            t90 = s.t;
        peak = std::max(peak, p);
    }
    m.rose = t90 >= 0.0;
    m.riseTime = m.rose ? t90 - std::max(0.0, t10) : 0.0;
    m.overshootPercent = std::max(0.0, (peak - 1.0) * 100.0);

    // Settled from the first sample after the last one outside the band;
    // a response whose last sample is outside never settled.
    const auto outside = [&](const PositionSample &s) { return std::fabs(s.position - step.target) > m.band; };
    const auto lastOutside = std::find_if(step.samples.rbegin(), step.samples.rend(), outside);
    if (lastOutside == step.samples.rbegin()) {
        m.settled = false;
        m.settlingTime = step.duration;
    } else if (lastOutside == step.samples.rend()) {
        m.settled = true;
        m.settlingTime = step.samples.front().t;
    } else {
        m.settled = true;
        m.settlingTime = (lastOutside - 1)->t; // the sample after it, in forward order
    }

    // Steady state: the time-weighted mean of the held values over the tail.
    const double end = std::max(step.duration, step.samples.back().t);
    const double from = end - m_settings.tailSeconds;
    double weighted = 0.0;
    double span = 0.0;
    for (qsizetype i = 0; i < step.samples.size(); ++i) {
        const double a = std::max(from, step.samples[i].t);
        const double b = i + 1 < step.samples.size() ? step.samples[i + 1].t : end;
        if (b > a) {
            weighted += step.samples[i].position * (b - a);
            span += b - a;
        }
    }
    const double rest = span > 0.0 ? weighted / span : step.samples.back().position;
    m.steadyStateError = step.target - rest;
    return m;
}

} // namespace slew::tuning
