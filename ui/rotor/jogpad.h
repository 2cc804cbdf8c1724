#pragma once
// Left/right/up/down buttons that move an axis while held, through the
// station's face (face/stationface.h): pressing starts a jog (a velocity
// move, or ML/MR/MU/MD, or SPID's go-to legs, where the dialect has no
// speed; from afar, a lease renewed while held), releasing stops that axis.
// The arrow keys drive the same buttons (KeyboardControl). A controller
// without speed commands (SPID) jogs at its own speed, so the speed box is
// greyed out for it and says why.

#include "face/stationface.h"

#include <QWidget>

class QDoubleSpinBox;
class QPushButton;

namespace slew::ui {

class JogPad : public QWidget {
    Q_OBJECT
public:
    enum Direction { Left, Right, Up, Down };
    Q_ENUM(Direction)

    explicit JogPad(face::StationFace *station, QWidget *parent = nullptr);

    double speed() const; // °/s
    bool isHeld(Direction d) const { return m_held[d]; }

public slots:
    void press(slew::ui::JogPad::Direction d);
    void release(slew::ui::JogPad::Direction d);
    void releaseAll(); // the window lost focus: nothing may keep moving

signals:
    // For the Events log: a jog the station took or was sent (its release
    // is a stop, logged as every stop is, "jog left released").
    void jogStarted(const QString &what);

private:
    void follow(const face::StationState &state);
    void followAxes(bool azimuthOnly); // an azimuth-only rotator has no up and down
    void followSpeed(const face::StationState &state); // a controller without speed commands ignores the box
    QPushButton *makeButton(Direction d, const QString &text, const QString &name);
    // The speed each axis is to turn at, from the buttons held: the one
    // pressed last of an axis' two.
    double axisSpeed(Direction negative, Direction positive) const;

    face::StationFace *m_station;
    QDoubleSpinBox *m_speed;
    QPushButton *m_buttons[4] = {};
    bool m_held[4] = {false, false, false, false};
    Direction m_lastPressed[2] = {Left, Up}; // per axis: azimuth, elevation
    bool m_azimuthOnly = false;
};

} // namespace slew::ui
