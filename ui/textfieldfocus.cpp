#include "textfieldfocus.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QEvent>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTextEdit>

namespace slew::ui {

bool isTextField(const QWidget *w)
{
    if (!w)
        return false;
    if (auto *line = qobject_cast<const QLineEdit *>(w))
        return !line->isReadOnly();
    if (auto *combo = qobject_cast<const QComboBox *>(w))
        return combo->isEditable();
    if (auto *text = qobject_cast<const QPlainTextEdit *>(w))
        return !text->isReadOnly();
    if (auto *text = qobject_cast<const QTextEdit *>(w))
        return !text->isReadOnly();
    return qobject_cast<const QAbstractSpinBox *>(w) != nullptr;
}

TextFieldFocus::TextFieldFocus(QWidget *window, QWidget *rest, QObject *parent)
    : QObject(parent), m_window(window), m_rest(rest)
{
    qApp->installEventFilter(this);
}

bool TextFieldFocus::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() != QEvent::MouseButtonPress)
        return false;
    auto *clicked = qobject_cast<QWidget *>(watched);
    if (!clicked || clicked->window() != m_window)
        return false;
    QWidget *field = QApplication::focusWidget();
    if (!isTextField(field))
        return false;
    // Qt gives a click's focus to the first widget up from the one clicked
    // that takes focus by clicking; only where there is none does the field
    // keep it, and that is the case handled here. Never seen on the way: the
    // field itself (its scroll bars, a spin box's arrows).
    for (QWidget *w = clicked; w; w = w->parentWidget()) {
        if (w == field || field->isAncestorOf(w))
            return false;
        if (w->isEnabled() && (w->focusPolicy() & Qt::ClickFocus))
            return false;
        if (w->isWindow())
            break;
    }
    m_rest->setFocus(Qt::MouseFocusReason);
    return false; // the click itself goes on as it would have
}

} // namespace slew::ui
