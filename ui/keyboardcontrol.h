#pragma once
// The window's keys, handled before any widget sees them: Esc stops the
// rotator from anywhere; arrow keys jog while held (auto-repeat ignored,
// release stops); number keys 1..9 recall presets. Typing into a field keeps
// its arrows and digits.
//
// Space is Stop wherever the focus is, with one exception: in a field that
// takes text (textfieldfocus.h) it is a space while the rotator is idle, and
// Stop while it moves (rotatormotion.h), because the operator who pressed
// Enter on a go-to and then Space wants the antenna stopped, and a field's
// stray space is cheap beside an antenna that keeps going.
//
// A held key must reach the jog pad as one press and one release. Qt marks
// autorepeat (isAutoRepeat) only when it sees the repeat's press already
// queued behind its release; on X11 a busy window often has not read it yet,
// and the pair arrives unmarked, 25 times a second. So a jog key's release
// waits kRepeatGraceMs for a press of the same key: one that comes is a
// repeat (the server sends the pair back to back, with one timestamp) and
// the axis runs on; none, and the release stops the axis.

#include <QObject>
#include <QTimer>

class QWidget;

namespace slew::ui {

class JogPad;
class PresetPanel;
class RotatorMotion;
class StopButton;

class KeyboardControl : public QObject {
    Q_OBJECT
public:
    KeyboardControl(QWidget *window, StopButton *stop, JogPad *jog, PresetPanel *presets, const RotatorMotion *motion,
                    QObject *parent = nullptr);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    static constexpr int kRepeatGraceMs = 30;

    bool isTyping() const;
    void jogKey(int direction, bool press);

    QWidget *m_window;
    StopButton *m_stop;
    JogPad *m_jog;
    PresetPanel *m_presets;
    const RotatorMotion *m_motion;
    bool m_spaceStops = false; // the last Space pressed in a text field was Stop
    QTimer m_release[4]; // per JogPad::Direction: a release waiting for its repeat
};

} // namespace slew::ui
