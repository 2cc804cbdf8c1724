// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Measures one axis' motion for the tracker: a kMotionStepDeg move from
// where the axis is, towards the side with room, recorded as a step
// (stepexperiment.h) and read by measureAxisMotion() (axismotion.h). The
// setup wizard's tuning page offers it next to tuning, whose small steps
// are too short for the axis to reach full speed.

#include "axismotion.h"
#include "stepexperiment.h"

#include <QObject>

namespace slew::session {
class RotatorSession;
}

namespace slew::tuning {

class MotionRun : public QObject {
    Q_OBJECT
public:
    explicit MotionRun(session::RotatorSession *session, QObject *parent = nullptr);

    // False with error() (and nothing sent) when the axis has no room for
    // the move or there is no position.
    bool start(session::Axis axis);
    void cancel();
    bool isRunning() const { return m_step.phase() == StepExperiment::Phase::Preparing
                                    || m_step.phase() == StepExperiment::Phase::Stepping; }
    QString error() const { return m_error; }
    StepExperiment &experiment() { return m_step; } // its samples, for a chart

signals:
    void measured(slew::session::Axis axis, const slew::tuning::AxisMotion &motion);
    void failed(const QString &reason);

private:
    session::RotatorSession *m_session;
    StepExperiment m_step;
    session::Axis m_axis = session::Axis::Azimuth;
    QString m_error;
};

} // namespace slew::tuning
