// SPDX-License-Identifier: GPL-3.0-or-later
#include "tracking/scheduletimeline.h"

#include "schedule/scheduletext.h"
#include "sky/utctime.h"

#include <QHelpEvent>
#include <QPainter>
#include <QToolTip>

#include <algorithm>
#include <cmath>

namespace slew::ui {

using schedule::ScheduledPass;

namespace {

constexpr int kLaneHeight = 18;
constexpr int kLaneGap = 4;
constexpr int kAxisHeight = 18;
constexpr int kNameWidth = 110;

const QColor kTaken(0x3f, 0xb9, 0x50);
const QColor kDropped(0x9a, 0x9f, 0xa8);
const QColor kCurrent(0xff, 0xd3, 0x4d);
const QColor kNow(0xe5, 0x48, 0x48);
const QColor kLaneBack(0x1a, 0x1f, 0x26);
const QColor kText(0xc9, 0xd1, 0xd9);

bool samePass(const ScheduledPass &a, const ScheduledPass &b)
{
    return a.target == b.target && std::abs(a.startJulian - b.startJulian) * sky::kSecondsPerDay < 1.0;
}

} // namespace

ScheduleTimeline::ScheduleTimeline(QWidget *parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("scheduleTimeline"));
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
}

void ScheduleTimeline::setSchedule(const schedule::Schedule &schedule)
{
    m_schedule = schedule;
    updateGeometry();
    update();
}

void ScheduleTimeline::setCurrent(const std::optional<ScheduledPass> &pass)
{
    m_current = pass;
    update();
}

double ScheduleTimeline::startJulian() const
{
    // An empty plan has no start of its own (0, a day in 4713 BC).
    return m_schedule.settings.startJulian > 0 ? m_schedule.settings.startJulian : m_now;
}

QString ScheduleTimeline::dayText() const
{
    if (!(startJulian() > 0))
        return {};
    return tr("UTC, %1").arg(sky::utcFromJulian(startJulian()).toString(QStringLiteral("d MMM")));
}

void ScheduleTimeline::setNow(double julian)
{
    m_now = julian;
    update();
}

int ScheduleTimeline::laneCount() const
{
    return std::max<int>(1, int(m_schedule.targets.size()));
}

QSize ScheduleTimeline::sizeHint() const
{
    return {480, kAxisHeight + laneCount() * (kLaneHeight + kLaneGap) + 4};
}

QSize ScheduleTimeline::minimumSizeHint() const
{
    return {kNameWidth + 160, sizeHint().height()};
}

QRectF ScheduleTimeline::plotArea() const
{
    return QRectF(kNameWidth, kAxisHeight, std::max(1, width() - kNameWidth - 4), height() - kAxisHeight);
}

double ScheduleTimeline::xFor(double julian) const
{
    const QRectF area = plotArea();
    const double start = startJulian();
    const double span = m_schedule.settings.hours / 24.0;
    if (!(span > 0))
        return area.left();
    return area.left() + area.width() * std::clamp((julian - start) / span, 0.0, 1.0);
}

QRectF ScheduleTimeline::barFor(const ScheduledPass &pass) const
{
    if (pass.priority < 0 || pass.priority >= laneCount())
        return {};
    const double top = kAxisHeight + pass.priority * (kLaneHeight + kLaneGap) + 2;
    const double left = xFor(pass.startJulian);
    const double right = std::max(left + 2.0, xFor(pass.endJulian)); // a short pass is still seen
    return QRectF(left, top, right - left, kLaneHeight);
}

const ScheduledPass *ScheduleTimeline::passAt(const QPointF &pos) const
{
    // Taken passes first: a dropped one may lie under it.
    for (bool taken : {true, false})
        for (const ScheduledPass &p : m_schedule.passes)
            if (p.taken == taken && barFor(p).adjusted(-2, 0, 2, 0).contains(pos))
                return &p;
    return nullptr;
}

bool ScheduleTimeline::event(QEvent *event)
{
    if (event->type() == QEvent::ToolTip) {
        auto *help = static_cast<QHelpEvent *>(event);
        if (const ScheduledPass *p = passAt(help->pos()))
            QToolTip::showText(help->globalPos(), schedule::describeScheduledPass(*p), this);
        else
            QToolTip::hideText();
        return true;
    }
    return QWidget::event(event);
}

void ScheduleTimeline::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QRectF area = plotArea();
    QFont small = font();
    small.setPointSizeF(small.pointSizeF() * 0.85);
    p.setFont(small);

    // The hours along the top, a tick every three.
    const double start = startJulian();
    p.setPen(kText);
    if (m_schedule.settings.hours > 0) {
        const double firstHour = std::ceil(start * 24.0 - 1e-9) / 24.0;
        for (double h = firstHour; h <= start + m_schedule.settings.hours / 24.0 + 1e-9; h += 1.0 / 24.0) {
            const double x = xFor(h);
            const int hour = sky::utcFromJulian(h + 1.0 / 86400.0).time().hour();
            p.setPen(QPen(QColor(0x30, 0x36, 0x3d), 1));
            p.drawLine(QPointF(x, area.top()), QPointF(x, area.bottom()));
            // Every third hour, where its label fits inside the time line.
            if (hour % 3 == 0 && x - 10 >= area.left() && x + 10 <= area.right() + 4) {
                p.setPen(kText);
                p.drawText(QRectF(x - 20, 0, 40, kAxisHeight), Qt::AlignCenter, QStringLiteral("%1").arg(hour, 2, 10, QLatin1Char('0')));
            }
        }
    }
    p.setPen(kText);
    p.drawText(QRectF(0, 0, kNameWidth - 4, kAxisHeight), Qt::AlignLeft | Qt::AlignVCenter, dayText());

    // A lane a target, its name at the left.
    for (int i = 0; i < m_schedule.targets.size(); ++i) {
        const double top = kAxisHeight + i * (kLaneHeight + kLaneGap) + 2;
        p.fillRect(QRectF(area.left(), top, area.width(), kLaneHeight), kLaneBack);
        p.setPen(kText);
        const QString name = QStringLiteral("%1. %2").arg(i + 1).arg(m_schedule.targets[i]);
        p.drawText(QRectF(0, top, kNameWidth - 6, kLaneHeight), Qt::AlignLeft | Qt::AlignVCenter,
                   p.fontMetrics().elidedText(name, Qt::ElideRight, kNameWidth - 6));
    }
    // Dropped under taken.
    for (const ScheduledPass &pass : m_schedule.passes) {
        if (pass.taken)
            continue;
        const QRectF bar = barFor(pass).adjusted(0, 3, 0, -3);
        p.setPen(QPen(kDropped, 1));
        p.setBrush(QBrush(kDropped, Qt::BDiagPattern));
        p.drawRect(bar);
    }
    for (const ScheduledPass &pass : m_schedule.passes) {
        if (!pass.taken)
            continue;
        const bool current = m_current && samePass(*m_current, pass);
        p.setPen(current ? QPen(kCurrent, 2) : Qt::NoPen);
        p.setBrush(kTaken);
        p.drawRoundedRect(barFor(pass), 2, 2);
    }
    // Now.
    if (m_now >= start && m_now <= start + m_schedule.settings.hours / 24.0) {
        p.setPen(QPen(kNow, 1.5));
        const double x = xFor(m_now);
        p.drawLine(QPointF(x, area.top()), QPointF(x, area.bottom()));
    }
}

} // namespace slew::ui
