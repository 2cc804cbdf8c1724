#include "tuningsequence.h"

namespace slew::tuning {

TuningSequence::TuningSequence(session::RotatorSession *session, QObject *parent)
    : QObject(parent), m_tuner(session)
{
    connect(&m_tuner, &AxisTuner::progress, this,
            [this](int percent, const QString &what) { emit progress(axisName(m_tuner.result().axis), percent, what); });
    connect(&m_tuner, &AxisTuner::resultReady, this, [this] {
        if (m_apply)
            m_tuner.accept();
        else
            m_tuner.keepOldGains();
    });
    connect(&m_tuner, &AxisTuner::finished, this, [this](const TuningResult &r) {
        m_results.append(r);
        emit axisDone(r);
        if (m_pending.isEmpty()) {
            emit finished(m_results);
        } else if (!next()) {
            emit failed(m_error);
        }
    });
    connect(&m_tuner, &AxisTuner::failed, this, &TuningSequence::failed);
    connect(&m_tuner, &AxisTuner::cancelled, this, &TuningSequence::failed);
}

bool TuningSequence::start(const QList<session::Axis> &axes, bool apply)
{
    if (axes.isEmpty()) {
        m_error = tr("no axis to tune");
        return false;
    }
    m_pending = axes;
    m_results.clear();
    m_apply = apply;
    return next();
}

bool TuningSequence::next()
{
    const session::Axis axis = m_pending.takeFirst();
    if (!m_tuner.start(axis)) {
        m_error = tr("%1: %2").arg(axisName(axis), m_tuner.error());
        return false;
    }
    return true;
}

} // namespace slew::tuning
