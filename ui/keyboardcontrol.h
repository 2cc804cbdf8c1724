#pragma once
// The window's keys, handled before any widget sees them: Esc and Pause
// stop the rotator from anywhere, a text field included; Space stops when
// no text field has the focus, and is a space in one; arrow keys jog while
// held (auto-repeat ignored, release stops). Typing into a field is only
// typing: its digits, spaces and arrows are the field's. A preset is
// Alt+1..9 (presetKey), never a bare digit, so a digit typed into a field
// that lost its focus moves nothing.
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
class StopButton;

class KeyboardControl : public QObject {
    Q_OBJECT
public:
    KeyboardControl(QWidget *window, StopButton *stop, JogPad *jog, QObject *parent = nullptr);

signals:
    // Alt+1..9: the operator asks for preset `index` (0-based); the window
    // recalls it, or asks first as for a plot click.
    void presetKey(int index);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    static constexpr int kRepeatGraceMs = 30;

    bool isTyping() const;
    void jogKey(int direction, bool press);

    QWidget *m_window;
    StopButton *m_stop;
    JogPad *m_jog;
    QTimer m_release[4]; // per JogPad::Direction: a release waiting for its repeat
};

} // namespace slew::ui
