#pragma once
// Before and after on one chart: position against time since the step, with
// the target, so the overshoot and the settling read at a glance.

#include "tuning/tuningresult.h"

#include <QChartView>

class QLineSeries;

namespace slew::ui {

class TuningChart : public QChartView {
    Q_OBJECT
public:
    explicit TuningChart(QWidget *parent = nullptr);

    void clear();
    // Live, while a step runs: the axes grow to take the sample in.
    void addSample(bool after, const tuning::PositionSample &sample);
    void showResult(const tuning::TuningResult &result);

private:
    void fit(double start, double target, double seconds);
    void niceTicks();

    QLineSeries *m_before;
    QLineSeries *m_after;
    QLineSeries *m_target;
};

} // namespace slew::ui
