#pragma once
// The big red Stop. It is never disabled: whatever the state, pressing it
// sends SA SE on any open link (the session puts it ahead of queued queries).
// Space and Esc press it from anywhere in the window (KeyboardControl).

#include "session/rotatorsession.h"

#include <QPushButton>

namespace slew::ui {

class StopButton : public QPushButton {
    Q_OBJECT
public:
    explicit StopButton(session::RotatorSession *session, QWidget *parent = nullptr);

public slots:
    bool stopAll();

signals:
    void stopped(); // after SA SE went out, so other panels can end what they were doing

private:
    session::RotatorSession *m_session;
};

} // namespace slew::ui
