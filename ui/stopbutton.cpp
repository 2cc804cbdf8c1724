#include "stopbutton.h"

namespace slew::ui {

StopButton::StopButton(session::RotatorSession *session, QWidget *parent)
    : StopButton([session](const QString &cause) { return bool(session->stop(cause)); }, parent)
{
}

StopButton::StopButton(std::function<bool(const QString &)> stop, QWidget *parent) : QPushButton(tr("STOP"), parent), m_stop(std::move(stop))
{
    setObjectName(QStringLiteral("stopButton"));
    setToolTip(tr("Stop both axes now (Esc or Pause anywhere; Space outside a text field)"));
    setAutoDefault(false);
    setFocusPolicy(Qt::NoFocus);
    // Big, but not so tall that the control column outgrows a 720-pixel
    // screen with an alarm shown; it takes more height when there is room.
    setMinimumHeight(46);
    QFont f = font();
    f.setPointSizeF(f.pointSizeF() * 1.6);
    f.setBold(true);
    setFont(f);
    setStyleSheet(QStringLiteral("QPushButton{background:#c62828;color:white;border:1px solid #8e1c1c;border-radius:6px;}"
                                 "QPushButton:pressed{background:#8e1c1c;}"));
    connect(this, &QPushButton::clicked, this, [this] { stopFor(tr("the STOP button")); });
}

bool StopButton::stopFor(const QString &cause)
{
    emit stopped(); // first: a running jog or homing must not restart the motion
    return m_stop(cause);
}

} // namespace slew::ui
