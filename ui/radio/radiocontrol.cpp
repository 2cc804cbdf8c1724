// SPDX-License-Identifier: GPL-3.0-or-later
#include "radio/radiocontrol.h"

#include "face/stationface.h"
#include "radio/frequencytext.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

namespace slew::ui {

QString describeRadio(const face::StationState &s)
{
    if (s.radioLink.isEmpty())
        return QObject::tr("Radio: the station does not say");
    if (s.radioLink == u"none")
        return s.radioHeld ? QObject::tr("Radio: none set · held by the operator")
                           : QObject::tr("Radio: none set");
    QStringList parts{QObject::tr("Radio: %1").arg(s.radioLink)};
    if (s.radioHeld)
        parts << QObject::tr("held by the operator: Doppler steering tunes nothing");
    else if (s.radioSteering)
        parts << QObject::tr("Doppler steering tunes it");
    else
        parts << QObject::tr("not tuned for a pass now");
    QStringList tuned;
    if (s.radioReceiveHz)
        tuned << QObject::tr("receive %1").arg(radio::groupedMegahertz(*s.radioReceiveHz));
    if (s.radioTransmitHz)
        tuned << QObject::tr("transmit %1").arg(radio::groupedMegahertz(*s.radioTransmitHz));
    if (!tuned.isEmpty())
        parts << tuned.join(QStringLiteral(", "));
    return parts.join(QStringLiteral(" · "));
}

RadioStateLine::RadioStateLine(face::StationFace *face, QWidget *parent) : QWidget(parent), m_face(face)
{
    m_line = new QLabel;
    m_line->setObjectName(QStringLiteral("radioState"));
    m_line->setWordWrap(true);
    m_line->setTextFormat(Qt::PlainText); // words from afar never format the window
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_line);
    connect(m_face, &face::StationFace::stateChanged, this, &RadioStateLine::showState);
    showState();
}

QString RadioStateLine::text() const
{
    return m_line->text();
}

void RadioStateLine::showState()
{
    const std::optional<face::StationState> s = m_face->state();
    m_line->setText(s ? describeRadio(*s) : tr("Radio: no word from the station yet"));
}

RadioControlButton::RadioControlButton(face::StationFace *face, QWidget *parent) : QWidget(parent), m_face(face)
{
    m_button = new QPushButton;
    m_button->setObjectName(QStringLiteral("radioHold"));
    m_button->setAutoDefault(false);
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_button);
    connect(m_button, &QPushButton::clicked, this, &RadioControlButton::toggle);
    connect(m_face, &face::StationFace::stateChanged, this, &RadioControlButton::showState);
    connect(m_face, &face::StationFace::liveChanged, this, &RadioControlButton::showState);
    connect(m_face, &face::StationFace::answered, this, [this](const QString &id, const face::Outcome &o) {
        if (id != m_awaiting)
            return;
        m_awaiting.clear();
        if (o.isRefused())
            emit message(tr("radio: %1").arg(o.reason()));
        showState();
    });
    showState();
}

void RadioControlButton::showState()
{
    const std::optional<face::StationState> s = m_face->state();
    const bool held = s && s->radioHeld;
    m_button->setText(held ? tr("Resume radio control") : tr("Stop radio control"));
    m_button->setToolTip(held ? tr("Tune the radio for Doppler again, from now on")
                              : tr("Send the radio nothing more: it stays where it is, for your hands, until resumed"));
    // Taking the dial is always offered, as Stop is; handing it back needs a
    // station that is there to hear it.
    m_button->setEnabled(s.has_value() && (!held || m_face->isLive()));
}

void RadioControlButton::toggle()
{
    const std::optional<face::StationState> s = m_face->state();
    if (!s)
        return;
    const face::Outcome asked = m_face->holdRadio(!s->radioHeld);
    if (asked.isRefused())
        emit message(tr("radio: %1").arg(asked.reason()));
    m_awaiting = asked.id();
}

} // namespace slew::ui
