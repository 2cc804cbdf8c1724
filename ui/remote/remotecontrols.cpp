// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/remotecontrols.h"

#include "operatortheme.h"

#include "face/stationface.h"
#include "remote/remotecommand.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace slew::ui {

RemoteControls::RemoteControls(face::StationFace *station, QWidget *parent) : QWidget(parent), m_station(station)
{
    m_target = new QLineEdit;
    m_target->setObjectName(QStringLiteral("remoteTrackTarget"));
    m_target->setPlaceholderText(tr("satellite, sun, moon, azel:AZ,EL"));
    m_target->setMaxLength(remote::kLongestTrackTarget);
    m_track = new QPushButton(tr("Track"));
    m_track->setObjectName(QStringLiteral("remoteTrack"));
    m_untrack = new QPushButton(tr("Stop tracking"));
    m_untrack->setObjectName(QStringLiteral("remoteUntrack"));
    // The name on a row of its own: the control column is narrow.
    auto *trackRow = new QHBoxLayout;
    trackRow->addWidget(m_track);
    trackRow->addWidget(m_untrack);

    m_message = new QLabel;
    m_message->setObjectName(QStringLiteral("remoteCommandMessage"));
    m_message->setTextFormat(Qt::PlainText);
    m_message->setWordWrap(true);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_target);
    layout->addLayout(trackRow);
    layout->addWidget(m_message);

    connect(m_track, &QPushButton::clicked, this, [this] {
        const QString target = m_target->text().trimmed();
        if (target.isEmpty()) {
            showMessage(tr("name a target to track"), true);
            return;
        }
        said(tr("track %1").arg(target), m_station->track(target, 0));
    });
    connect(m_untrack, &QPushButton::clicked, this, [this] { said(tr("stop tracking"), m_station->untrack()); });
    connect(station, &face::StationFace::answered, this, [this](const QString &id, const face::Outcome &outcome) {
        if (const auto it = m_awaiting.constFind(id); it != m_awaiting.cend()) {
            const QString what = *it;
            m_awaiting.erase(it);
            said(what, outcome);
        }
    });
}

void RemoteControls::said(const QString &what, const face::Outcome &outcome)
{
    if (outcome.isAwaiting()) {
        // Answers that never come are said by the face (no reply in time).
        m_awaiting.insert(outcome.id(), what);
        showMessage(tr("%1: sent").arg(what), false);
    } else if (outcome.isRefused()) {
        showMessage(tr("%1 refused: %2").arg(what, outcome.reason()), true);
    } else {
        showMessage(tr("%1: accepted by the station").arg(what), false);
    }
}

QString RemoteControls::message() const
{
    return m_message->text();
}

void RemoteControls::showMessage(const QString &text, bool problem)
{
    m_message->setText(text);
    m_message->setStyleSheet(problem ? warningText() : QString());
}

void RemoteControls::setLive(bool live)
{
    for (QWidget *w : std::initializer_list<QWidget *>{m_target, m_track, m_untrack})
        w->setEnabled(live);
}

} // namespace slew::ui
