#include "keyboardcontrol.h"

#include "rotor/jogpad.h"
#include "stopbutton.h"
#include "textfieldfocus.h"

#include <QApplication>
#include <QKeyEvent>

namespace slew::ui {

namespace {

std::optional<JogPad::Direction> jogDirection(int key)
{
    switch (key) {
    case Qt::Key_Left: return JogPad::Left;
    case Qt::Key_Right: return JogPad::Right;
    case Qt::Key_Up: return JogPad::Up;
    case Qt::Key_Down: return JogPad::Down;
    default: return std::nullopt;
    }
}

} // namespace

KeyboardControl::KeyboardControl(QWidget *window, StopButton *stop, JogPad *jog, QObject *parent)
    : QObject(parent), m_window(window), m_stop(stop), m_jog(jog)
{
    qApp->installEventFilter(this);
    for (int d = 0; d < 4; ++d) {
        m_release[d].setSingleShot(true);
        m_release[d].setInterval(kRepeatGraceMs);
        connect(&m_release[d], &QTimer::timeout, this, [this, d] { m_jog->release(JogPad::Direction(d)); });
    }
    // A Stop releases every jog (StationWindow); a release still waiting must
    // not be taken for the start of a repeat afterwards.
    connect(m_stop, &StopButton::stopped, this, [this] {
        for (QTimer &t : m_release)
            t.stop();
    });
    // Keys released while another application has focus never arrive here:
    // losing focus must not leave an axis running.
    connect(qApp, &QApplication::applicationStateChanged, this, [this](Qt::ApplicationState s) {
        if (s != Qt::ApplicationActive)
            m_jog->releaseAll();
    });
}

bool KeyboardControl::isTyping() const
{
    return isTextField(QApplication::focusWidget());
}

bool KeyboardControl::eventFilter(QObject *watched, QEvent *event)
{
    const QEvent::Type type = event->type();
    if (type != QEvent::KeyPress && type != QEvent::KeyRelease && type != QEvent::ShortcutOverride)
        return false;
    auto *widget = qobject_cast<QWidget *>(watched);
    if (!widget || widget->window() != m_window)
        return false;
    auto *key = static_cast<QKeyEvent *>(event);
    const int k = key->key();
    const Qt::KeyboardModifiers modifiers = key->modifiers() & ~Qt::KeypadModifier;

    // Esc and Pause stop from anywhere, whatever else is held; Space only
    // where it types nothing.
    const bool alwaysStop = k == Qt::Key_Escape || k == Qt::Key_Pause;
    const bool typing = isTyping();
    if (alwaysStop || (k == Qt::Key_Space && modifiers == Qt::NoModifier && !typing)) {
        if (type == QEvent::ShortcutOverride) {
            event->accept(); // keep a shortcut from taking it
            return false;
        }
        if (type == QEvent::KeyPress && !key->isAutoRepeat())
            m_stop->stopFor(k == Qt::Key_Escape ? tr("the Esc key") : k == Qt::Key_Pause ? tr("the Pause key") : tr("the Space key"));
        return true;
    }
    // Alt+1..9: a preset, asked for on purpose.
    if (modifiers == Qt::AltModifier && k >= Qt::Key_1 && k <= Qt::Key_9) {
        if (type == QEvent::ShortcutOverride) {
            event->accept();
            return false;
        }
        if (type == QEvent::KeyPress && !key->isAutoRepeat())
            emit presetKey(k - Qt::Key_1);
        return true;
    }
    if (modifiers != Qt::NoModifier || typing || type == QEvent::ShortcutOverride)
        return false;
    if (const auto d = jogDirection(k)) {
        if (!key->isAutoRepeat())
            jogKey(*d, type == QEvent::KeyPress);
        return true;
    }
    return false;
}

void KeyboardControl::jogKey(int direction, bool press)
{
    const auto d = JogPad::Direction(direction);
    QTimer &pending = m_release[d];
    if (press) {
        if (pending.isActive()) // the press of an unmarked repeat: the axis runs on
            pending.stop();
        else
            m_jog->press(d);
        return;
    }
    if (m_jog->isHeld(d))
        pending.start(); // stops the axis unless a repeat's press comes first
}

} // namespace slew::ui
