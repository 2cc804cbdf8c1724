// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/remotescheduleview.h"

#include "tracking/scheduletimeline.h"

#include "remote/stationschedule.h"
#include "schedule/scheduletext.h"

#include <QLabel>
#include <QVBoxLayout>

namespace slew::ui {
namespace {

double julianOf(qint64 unixMs)
{
    return 2440587.5 + double(unixMs) / 86400000.0;
}

} // namespace

RemoteScheduleView::RemoteScheduleView(QWidget *parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("remoteScheduleView"));
    m_summary = new QLabel(tr("The station has published no schedule."));
    m_summary->setObjectName(QStringLiteral("remoteScheduleSummary"));
    m_summary->setWordWrap(true);
    m_current = new QLabel;
    m_current->setObjectName(QStringLiteral("remoteScheduleCurrent"));
    m_current->setWordWrap(true);
    m_current->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_timeline = new ScheduleTimeline;
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_summary);
    layout->addWidget(m_timeline);
    layout->addWidget(m_current);
    layout->addStretch(1);
}

void RemoteScheduleView::showSchedule(const face::StationSchedule &s, qint64 receivedUnixMs)
{
    m_running = s.running;
    m_clockMs = s.clockMs;
    m_receivedMs = receivedUnixMs;
    m_rate = s.clockRate;
    if (!s.running) {
        m_summary->setText(tr("The station runs no schedule."));
        m_current->clear();
        m_timeline->setSchedule({});
        m_timeline->setCurrent(std::nullopt);
        return;
    }
    if (!s.planned) {
        m_summary->setText(tr("The station is making its schedule."));
        m_current->clear();
        m_timeline->setSchedule({});
        m_timeline->setCurrent(std::nullopt);
        return;
    }
    m_summary->setText(tr("By priority: %1. %2.")
                           .arg(s.schedule.targets.join(QStringLiteral(", ")),
                                schedule::describeScheduleSummary(s.schedule)));
    m_timeline->setSchedule(s.schedule);
    const std::optional<schedule::ScheduledPass> current =
        s.current ? std::optional(s.schedule.passes.at(*s.current)) : std::nullopt;
    m_timeline->setCurrent(current);
    m_current->setText(current ? tr("Now: %1").arg(schedule::describeScheduledPass(*current))
                               : tr("No pass is being followed."));
    showTime(receivedUnixMs);
}

void RemoteScheduleView::showTime(qint64 unixMs)
{
    if (!m_running)
        return;
    const double clockMs = double(m_clockMs) + double(unixMs - m_receivedMs) * m_rate;
    m_timeline->setNow(julianOf(qint64(clockMs)));
}

QString RemoteScheduleView::summary() const
{
    return m_summary->text();
}

QString RemoteScheduleView::currentText() const
{
    return m_current->text();
}

} // namespace slew::ui
