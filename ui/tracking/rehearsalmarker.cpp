// SPDX-License-Identifier: GPL-3.0-or-later
#include "tracking/rehearsalmarker.h"

#include "sky/utctime.h"
#include "tracking/stationclock.h"

#include <QEvent>
#include <QMainWindow>
#include <QStatusBar>

namespace slew::ui {

RehearsalMarker::RehearsalMarker(const tracking::StationClock *clock, QMainWindow *window)
    : QLabel(window), m_clock(clock), m_titled(window)
{
    setObjectName(QStringLiteral("rehearsalMarker"));
    setStyleSheet(markStyle());
    setToolTip(tr("The station clock is not real time: the passes, the plot and tracking follow it. "
                  "Sky → Time controller… goes back to real time."));
    // The window sets its own title as the link comes and goes: mark
    // whatever it sets.
    m_titled->installEventFilter(this);
    connect(m_clock, &tracking::StationClock::changed, this, &RehearsalMarker::refresh);
    // A pause of real time starts a rehearsal without a new plan: said at once too.
    connect(m_clock, &tracking::StationClock::pausedChanged, this, &RehearsalMarker::refresh);
    connect(m_clock, &tracking::StationClock::stepped, this, &RehearsalMarker::refresh);
    connect(&m_tick, &QTimer::timeout, this, &RehearsalMarker::refresh);
    m_tick.start(1000);
    // In the status bar first: it shows what it is given, and the marker
    // is then hidden in real time.
    window->statusBar()->addPermanentWidget(this);
    refresh();
}

QString RehearsalMarker::clockText(double julian)
{
    return sky::utcFromJulian(julian).toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")) + QStringLiteral(" UTC");
}

QString RehearsalMarker::markStyle()
{
    // Orange on dark text: unlike the amber alarm banner and the status
    // bar's grey, and readable at a glance across the shack.
    return QStringLiteral("background:#f07818; color:#1a1a1a; font-weight:bold; padding:1px 8px; border-radius:3px;");
}

QString RehearsalMarker::rateText(double rate)
{
    return QStringLiteral("×") + QString::number(rate, 'g', 3);
}

void RehearsalMarker::refresh()
{
    const bool rehearsal = m_clock->isRehearsal();
    if (rehearsal)
        setText(tr("REHEARSAL: station clock %1 %2%3")
                    .arg(clockText(m_clock->nowJulian()), rateText(m_clock->rate()),
                         m_clock->isPaused() ? tr(", paused") : QString()));
    setVisible(rehearsal);
    markTitle();
}

void RehearsalMarker::markTitle()
{
    const QString prefix = m_clock->isRehearsal() ? tr("REHEARSAL %1 — ").arg(rateText(m_clock->rate())) : QString();
    QString title = m_titled->windowTitle();
    if (!m_titlePrefix.isEmpty() && title.startsWith(m_titlePrefix))
        title.remove(0, m_titlePrefix.size());
    m_titlePrefix = prefix;
    const QString marked = prefix + title;
    if (marked == m_titled->windowTitle())
        return;
    m_retitling = true;
    m_titled->setWindowTitle(marked);
    m_retitling = false;
}

bool RehearsalMarker::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_titled && event->type() == QEvent::WindowTitleChange && !m_retitling
        && !m_titlePrefix.isEmpty() && !m_titled->windowTitle().startsWith(m_titlePrefix))
        markTitle();
    return QLabel::eventFilter(watched, event);
}

} // namespace slew::ui
