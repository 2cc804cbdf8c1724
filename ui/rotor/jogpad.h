#pragma once
// Left/right/up/down buttons that move an axis while held: pressing starts a
// velocity move (or ML/MR/MU/MD, or SPID's go-to legs, where the dialect has
// no speed), releasing stops that axis. The arrow keys drive the same buttons (KeyboardControl).
// A controller without speed commands (SPID) jogs at its own speed, so the
// speed box is greyed out for it and says why.

#include "session/rotatorsession.h"

#include <QWidget>

class QDoubleSpinBox;
class QPushButton;

namespace slew::ui {

class JogPad : public QWidget {
    Q_OBJECT
public:
    enum Direction { Left, Right, Up, Down };
    Q_ENUM(Direction)

    explicit JogPad(session::RotatorSession *session, QWidget *parent = nullptr);

    double speed() const; // °/s
    bool isHeld(Direction d) const { return m_held[d]; }

public slots:
    void press(slew::ui::JogPad::Direction d);
    void release(slew::ui::JogPad::Direction d);
    void releaseAll(); // the window lost focus: nothing may keep moving

signals:
    // For the Events log: a jog the session sent (its release is a stop,
    // logged as every stop is, "jog left released").
    void jogStarted(const QString &what);

private:
    void followAxes(); // an azimuth-only rotator has no up and down
    void followSpeed(); // a controller without speed commands ignores the box
    QPushButton *makeButton(Direction d, const QString &text, const QString &name);

    session::RotatorSession *m_session;
    QDoubleSpinBox *m_speed;
    QPushButton *m_buttons[4] = {};
    bool m_held[4] = {false, false, false, false};
    bool m_sent[4] = {false, false, false, false}; // the held jog reached the wire
};

} // namespace slew::ui
