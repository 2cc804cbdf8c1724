#pragma once
// The big red Stop. It is never disabled: whatever the state, pressing it
// sends SA SE on any open link (the session puts it ahead of queued queries).
// Esc and Pause press it from anywhere in the window, Space from outside a
// text field (KeyboardControl).
// What a stop is belongs to whoever makes the button: the operator window's
// is the Station's Stop (every rotor, trackers held off), the wizard's its
// session's.

#include "session/rotatorsession.h"

#include <QPushButton>

#include <functional>

namespace slew::ui {

class StopButton : public QPushButton {
    Q_OBJECT
public:
    explicit StopButton(session::RotatorSession *session, QWidget *parent = nullptr);
    // Stops with `stop`, given what asked ("the STOP button", "the Esc
    // key") for the logs; it says whether a stop went out.
    explicit StopButton(std::function<bool(const QString &cause)> stop, QWidget *parent = nullptr);

public slots:
    bool stopFor(const QString &cause);

signals:
    // Before the stop goes out: a running jog or homing ends first, so it
    // cannot send a move after the stop.
    void stopped();

private:
    std::function<bool(const QString &)> m_stop;
};

} // namespace slew::ui
