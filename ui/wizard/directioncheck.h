// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One axis' direction check on the Mechanics page: a short go-to from where
// the axis stands, watched through the controller's reading. A reading that
// runs the other way (a motor wired the wrong way round, a sensor that
// counts backwards) stops the rotator at once and fails the check: the
// controller's loop would otherwise drive it on into its end stop.
// A reading that goes the right way is not the whole answer (a motor and a
// sensor both reversed read as right while the antenna turns the wrong way),
// so the operator still confirms what the antenna did.

#include "session/sessiontypes.h"

#include <QMetaObject>
#include <QObject>

namespace slew::session {
class RotatorSession;
}

namespace slew::ui {

class DirectionCheck : public QObject {
    Q_OBJECT
public:
    enum class Verdict {
        NotRun,   // no jog yet
        Watching, // the jog went out; the reading has not yet said which way
        RightWay, // the reading went most of the way towards the target
        WrongWay, // the reading ran the other way; the rotator was stopped
        Stopped,  // stopped before the reading said which way
    };

    DirectionCheck(session::RotatorSession *session, session::Axis axis, QObject *parent = nullptr);

    // Jogs the axis `degrees` up (clockwise), or down (counter-clockwise)
    // when up would leave the limits, through the session's limits gate.
    // False, with error(), when the session refused it: nothing moved.
    bool start(double degrees);
    // The wizard's STOP: the watch ends where it is (the wizard stops the
    // rotator itself).
    void stop();

    Verdict verdict() const { return m_verdict; }
    session::Axis axis() const { return m_axis; }
    bool upward() const { return m_upward; } // the last jog: up, or clockwise
    QString error() const { return m_error; }
    // The way the last jog went, in the operator's words: "clockwise", "up".
    QString way() const;
    // What the operator reads about the verdict.
    QString describe() const;

signals:
    void verdictChanged();

private:
    void onPosition();
    void conclude(Verdict verdict);
    double reading() const;

    session::RotatorSession *m_session;
    session::Axis m_axis;
    Verdict m_verdict = Verdict::NotRun;
    bool m_upward = true;
    double m_from = 0.0;
    double m_target = 0.0;
    double m_wrongReading = 0.0; // where a wrong-way reading was caught
    QString m_error;
    QMetaObject::Connection m_watch;
};

} // namespace slew::ui
