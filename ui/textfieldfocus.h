#pragma once
// Which widgets take typed text, and getting the focus out of one: a click
// on something that takes no focus itself (a tab, a group box, a label, the
// plot) hands the focus to a resting widget that types nothing, so Space and
// the arrow keys are the window's again (KeyboardControl).

#include <QObject>

class QWidget;

namespace slew::ui {

// A field the operator types into: an editable line, combo box, text box or
// spin box. Space, arrows and digits belong to it while it has the focus.
bool isTextField(const QWidget *w);

class TextFieldFocus : public QObject {
    Q_OBJECT
public:
    // rest: where the focus goes from a text field when the operator clicks
    // beside it; a widget that takes no typing.
    TextFieldFocus(QWidget *window, QWidget *rest, QObject *parent = nullptr);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    QWidget *m_window;
    QWidget *m_rest;
};

} // namespace slew::ui
