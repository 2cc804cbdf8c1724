#pragma once
// The window's keys, handled before any widget sees them: Esc stops the
// rotator from anywhere; Space stops it too unless the operator is typing
// into a text field; arrow keys jog while held (auto-repeat ignored, release
// stops); number keys 1..9 recall presets. Typing into a field keeps its
// arrows, digits and spaces.

#include <QObject>

class QWidget;

namespace slew::ui {

class JogPad;
class PresetPanel;
class StopButton;

class KeyboardControl : public QObject {
    Q_OBJECT
public:
    KeyboardControl(QWidget *window, StopButton *stop, JogPad *jog, PresetPanel *presets, QObject *parent = nullptr);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    bool isTyping() const;

    QWidget *m_window;
    StopButton *m_stop;
    JogPad *m_jog;
    PresetPanel *m_presets;
};

} // namespace slew::ui
