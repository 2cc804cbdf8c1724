// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/remotebanner.h"

#include "remote/remotestation.h"

namespace slew::ui {

RemoteBanner::RemoteBanner(remote::RemoteStation *station, QWidget *parent) : QLabel(parent), m_station(station)
{
    setObjectName(QStringLiteral("remoteBanner"));
    setTextFormat(Qt::PlainText);
    setWordWrap(true);
    setMargin(6);
    // The age is shown to a tenth of a second while it is small.
    m_tick.setInterval(250);
    connect(&m_tick, &QTimer::timeout, this, &RemoteBanner::refresh);
    m_tick.start();
    connect(station, &remote::RemoteStation::liveChanged, this, &RemoteBanner::refresh);
    connect(station, &remote::RemoteStation::stateChanged, this, &RemoteBanner::refresh);
    refresh();
}

QString RemoteBanner::ageText(qint64 ageMs)
{
    if (ageMs < 0)
        return tr("no state yet");
    if (ageMs < 10000)
        return tr("state %1 s old").arg(double(ageMs) / 1000.0, 0, 'f', 1);
    if (ageMs < 120000)
        return tr("state %1 s old").arg(ageMs / 1000);
    return tr("state %1 min old").arg(ageMs / 60000);
}

void RemoteBanner::refresh()
{
    const QString where = tr("REMOTE: station %1 on %2").arg(m_station->name(), m_station->brokerDisplay());
    const QString age = ageText(m_station->stateAgeMs());
    if (m_station->isLive()) {
        setText(tr("%1 · %2").arg(where, age));
        setStyleSheet(QStringLiteral("#remoteBanner{background:#1e4b7a;color:white;font-weight:bold;}"));
    } else {
        setText(tr("%1 · NOT LIVE: %2 · last %3").arg(where, m_station->whyNotLive(), age));
        setStyleSheet(QStringLiteral("#remoteBanner{background:#4a4f57;color:#f2c14e;font-weight:bold;}"));
    }
}

} // namespace slew::ui
