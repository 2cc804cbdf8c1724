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
    // Stops with `stop`, which says whether a stop went out.
    explicit StopButton(std::function<bool()> stop, QWidget *parent = nullptr);

    // What asked for the last stop, for the event log: "the STOP button",
    // "the Esc key".
    QString lastCause() const { return m_lastCause; }

public slots:
    bool stopAll();
    bool stopFor(const QString &cause);

signals:
    void stopped(); // after SA SE went out, so other panels can end what they were doing

private:
    std::function<bool()> m_stop;
    QString m_lastCause;
};

} // namespace slew::ui
