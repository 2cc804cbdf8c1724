#pragma once
// Where the rotator is, in large figures, with the target and what GS says
// each axis is doing. Dimmed when the position is stale.

#include "session/rotatorsession.h"

#include <QWidget>

class QLabel;

namespace slew::ui {

// A figure rounded to a tenth for display, never "-0.0".
double shownTenths(double value);

class PositionReadout : public QWidget {
    Q_OBJECT
public:
    explicit PositionReadout(session::RotatorSession *session, QWidget *parent = nullptr);

private:
    void showPosition(double az, double el, bool stale);
    void showStatus(session::StatusWord status);

    QLabel *m_az;
    QLabel *m_el;
    QLabel *m_target;
    QLabel *m_status;
};

} // namespace slew::ui
