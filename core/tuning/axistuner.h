// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Tunes one axis end to end on the live controller:
//
//   read the gains (CR) → step with them → fit a model → propose gains →
//   write them (CW, read back) → step again → wait for the operator
//
// and then keeps the new gains (accept) or writes the old ones back
// (keepOldGains, retry). Cancel at any point stops the axis and, if trial
// gains were written, restores the old ones: the controller is left as it
// was unless the operator accepted.

#include "gainproposer.h"
#include "registerreadback.h"
#include "stepexperiment.h"
#include "stepresponseanalyzer.h"
#include "tuningresult.h"

#include <QObject>

namespace slew::session {
class RotatorSession;
}

namespace slew::tuning {

struct TuningSettings {
    // Degrees: small enough that the drive stays out of its speed and
    // acceleration limits, where the fitted model holds. A G-5500 class
    // elevation (2.7 deg/s) runs into its speed cap on a 4 degree step.
    double amplitude = 2.0;
    StepSettings step;
    AnalysisSettings analysis;
    ProposalSettings proposal;
};

class AxisTuner : public QObject {
    Q_OBJECT
public:
    enum class Phase { Idle, ReadingGains, MeasuringBefore, Proposing, WritingTrial, MeasuringAfter,
                       AwaitingDecision, Restoring, Done, Cancelled, Failed };
    Q_ENUM(Phase)

    explicit AxisTuner(session::RotatorSession *session, QObject *parent = nullptr);

    void setSettings(const TuningSettings &settings) { m_settings = settings; }
    const TuningSettings &settings() const { return m_settings; }

    // Starts; false with error() set (and nothing sent) when it cannot.
    bool start(session::Axis axis);
    bool isRunning() const;
    Phase phase() const { return m_phase; }
    QString error() const { return m_error; }
    const TuningResult &result() const { return m_result; }

public slots:
    // After resultReady: keep the gains on the controller.
    void accept();
    // After resultReady: write the old gains back.
    void keepOldGains();
    // After resultReady: old gains back, then tune again.
    void retry();
    // Any time: stop the axis, restore the registers, end.
    void cancel();

signals:
    void progress(int percent, const QString &what);
    void sampleRecorded(bool after, const slew::tuning::PositionSample &sample);
    void resultReady(const slew::tuning::TuningResult &result); // waiting for accept / keep / retry
    void finished(const slew::tuning::TuningResult &result);    // done; result.applied says which gains stay
    void cancelled(const QString &why);
    void failed(const QString &reason);

private:
    void setPhase(Phase p, int percent, const QString &what);
    void onGainsRead(bool ok);
    void onStepFinished(const StepResponse &response);
    void onStepFailed(const QString &reason);
    void onTrialWritten(bool ok);
    void onRestored(bool ok);
    bool writeGains(const model::PidGains &gains);
    void startStep();
    void fail(const QString &reason);

    session::RotatorSession *m_session;
    TuningSettings m_settings;
    StepExperiment m_step;
    RegisterReadback m_registers;
    Phase m_phase = Phase::Idle;
    Phase m_afterRestore = Phase::Done;
    session::Axis m_axis = session::Axis::Azimuth;
    double m_from = 0.0, m_to = 0.0;
    bool m_trialWritten = false;
    TuningResult m_result;
    QString m_error;
    QString m_cancelReason;
};

} // namespace slew::tuning
