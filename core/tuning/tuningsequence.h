#pragma once
// Tunes several axes one after the other and decides each without asking:
// keep the new gains (apply) or write the old ones back. What `slew --tune`
// runs; the wizard asks the operator instead.

#include "axistuner.h"

#include <QList>
#include <QObject>

namespace slew::tuning {

class TuningSequence : public QObject {
    Q_OBJECT
public:
    TuningSequence(session::RotatorSession *session, QObject *parent = nullptr);

    void setSettings(const TuningSettings &settings) { m_tuner.setSettings(settings); }
    // Starts with the first axis; false with error() when it cannot start.
    bool start(const QList<session::Axis> &axes, bool apply);
    void cancel() { m_tuner.cancel(); }
    QString error() const { return m_error; }
    const QList<TuningResult> &results() const { return m_results; }
    AxisTuner &tuner() { return m_tuner; }

signals:
    void progress(const QString &axis, int percent, const QString &what);
    void axisDone(const slew::tuning::TuningResult &result);
    void finished(const QList<slew::tuning::TuningResult> &results);
    void failed(const QString &reason);

private:
    bool next();

    AxisTuner m_tuner;
    QList<session::Axis> m_pending;
    QList<TuningResult> m_results;
    bool m_apply = false;
    QString m_error;
};

} // namespace slew::tuning
