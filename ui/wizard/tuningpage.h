#pragma once
// Step 5: one axis at a time — step, fit, propose, try the gains, and show
// before and after on one chart with the figures side by side. The operator
// accepts, retries, or keeps the old gains. The wizard's STOP ends a run.

#include "tuning/axistuner.h"
#include "tuning/motionrun.h"

#include <QWizardPage>

class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;

namespace slew::ui {

class SetupWizard;
class TuningChart;

class TuningPage : public QWizardPage {
    Q_OBJECT
public:
    explicit TuningPage(SetupWizard *wizard);
    bool isComplete() const override;

private:
    void start();
    void measureSpeed();
    void showResult(const tuning::TuningResult &r);
    void setDeciding(bool deciding);
    static QString figures(const QString &title, const tuning::StepMetrics &m, const model::PidGains &g);

    SetupWizard *m_wizard;
    tuning::AxisTuner m_tuner;
    tuning::MotionRun m_motionRun; // the axis' speed for the tracker
    QComboBox *m_axis;
    QPushButton *m_tune;
    QPushButton *m_measureSpeed;
    QProgressBar *m_progress;
    QLabel *m_status;
    TuningChart *m_chart;
    QLabel *m_before;
    QLabel *m_after;
    QPushButton *m_accept;
    QPushButton *m_retry;
    QPushButton *m_keepOld;
};

} // namespace slew::ui
