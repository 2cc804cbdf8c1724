// SPDX-License-Identifier: GPL-3.0-or-later
#include "telemetry/statuslaneview.h"

#include <QCategoryAxis>
#include <QDateTime>
#include <QFontMetricsF>
#include <QHelpEvent>
#include <QPainter>
#include <QToolTip>

#include <algorithm>

namespace slew::ui {

namespace {

constexpr double kBarShare = 0.7; // of a lane's height; the rest keeps lanes apart

QString clockTime(qint64 ms)
{
    return QDateTime::fromMSecsSinceEpoch(ms).toString(QStringLiteral("HH:mm:ss"));
}

} // namespace

StatusLaneView::StatusLaneView(QChart *chart, std::vector<Lane> lanes, QWidget *parent)
    : QChartView(chart, parent), m_lanes(std::move(lanes)), m_stretches(m_lanes.size())
{
    m_axis = new QCategoryAxis;
    m_axis->setLabelsPosition(QCategoryAxis::AxisLabelsPositionCenter);
    m_axis->setGridLineVisible(false);
    // Qt Charts cuts a category's name to "..." once the lane is lower than
    // a quarter of the chart less some padding; the names are short, and
    // the lanes are what this chart is for.
    m_axis->setTruncateLabels(false);
    chart->addAxis(m_axis, Qt::AlignLeft);
    rebuildAxis();
}

std::vector<int> StatusLaneView::shownLanes() const
{
    std::vector<int> out;
    for (int i = 0; i < int(m_lanes.size()); ++i) {
        if (m_lanes[size_t(i)].shown)
            out.push_back(i);
    }
    return out;
}

void StatusLaneView::rebuildAxis()
{
    // Categories count up from the bottom; the lanes are listed from the top.
    for (const QString &label : m_axis->categoriesLabels())
        m_axis->remove(label);
    const std::vector<int> shown = shownLanes();
    m_axis->setStartValue(0);
    for (std::size_t k = 0; k < shown.size(); ++k)
        m_axis->append(m_lanes[size_t(shown[shown.size() - 1 - k])].name, double(k + 1));
    m_axis->setRange(0, double(std::max<std::size_t>(1, shown.size())));
    viewport()->update();
}

void StatusLaneView::setLaneShown(int lane, bool shown)
{
    if (lane < 0 || lane >= int(m_lanes.size()) || m_lanes[size_t(lane)].shown == shown)
        return;
    m_lanes[size_t(lane)].shown = shown;
    rebuildAxis();
}

void StatusLaneView::setStretches(qint64 fromMs, qint64 toMs, std::vector<std::vector<StatusStretch>> perLane)
{
    m_fromMs = fromMs;
    m_toMs = std::max(toMs, fromMs + 1);
    perLane.resize(m_lanes.size());
    m_stretches = std::move(perLane);
    viewport()->update();
}

QRectF StatusLaneView::plotInScene() const
{
    return chart()->mapRectToScene(chart()->plotArea());
}

void StatusLaneView::drawForeground(QPainter *painter, const QRectF &rect)
{
    QChartView::drawForeground(painter, rect);
    const std::vector<int> shown = shownLanes();
    const QRectF plot = plotInScene();
    if (shown.empty() || plot.width() < 1)
        return;
    const double laneHeight = plot.height() / double(shown.size());
    const double perMs = plot.width() / double(m_toMs - m_fromMs);
    QFont font = m_axis->labelsFont();
    painter->save();
    painter->setClipRect(plot);
    painter->setFont(font);
    const QFontMetricsF metrics(font);
    for (std::size_t row = 0; row < shown.size(); ++row) {
        const Lane &lane = m_lanes[size_t(shown[row])];
        const double top = plot.top() + laneHeight * double(row) + laneHeight * (1 - kBarShare) / 2;
        for (const StatusStretch &s : m_stretches[size_t(shown[row])]) {
            const double left = plot.left() + double(s.fromMs - m_fromMs) * perMs;
            const double right = plot.left() + double(s.toMs - m_fromMs) * perMs;
            const QRectF bar(QPointF(left, top), QPointF(std::max(right, left + 1), top + laneHeight * kBarShare));
            painter->fillRect(bar, toneColour(toneOf(lane.reg, s.bits)));
            // The names, where there is room for some of them: the
            // tooltip has them all.
            const QRectF room = bar.intersected(plot).adjusted(3, 0, -3, 0);
            const QString name = fittedStateName(stateName(lane.reg, s.bits), metrics, room.width());
            if (name.isEmpty())
                continue;
            painter->setPen(Qt::white);
            painter->drawText(room, Qt::AlignVCenter | Qt::AlignLeft, name);
        }
    }
    painter->restore();
}

QString StatusLaneView::describeAt(QPoint pos) const
{
    const std::vector<int> shown = shownLanes();
    const QRectF plot = plotInScene();
    const QPointF at = mapToScene(pos);
    if (shown.empty() || !plot.contains(at))
        return {};
    const auto row = std::min<std::size_t>(shown.size() - 1, std::size_t((at.y() - plot.top()) / plot.height() * double(shown.size())));
    const int lane = shown[row];
    const qint64 t = m_fromMs + qint64((at.x() - plot.left()) / plot.width() * double(m_toMs - m_fromMs));
    for (const StatusStretch &s : m_stretches[size_t(lane)]) {
        if (t >= s.fromMs && t <= s.toMs) {
            const Lane &l = m_lanes[size_t(lane)];
            return tr("%1 %2–%3: %4 (%5)")
                .arg(l.name, clockTime(s.fromMs), clockTime(s.toMs), stateName(l.reg, s.bits), hexValue(s.bits));
        }
    }
    return tr("%1: nothing reported").arg(m_lanes[size_t(lane)].name);
}

bool StatusLaneView::viewportEvent(QEvent *event)
{
    if (event->type() == QEvent::ToolTip) {
        auto *help = static_cast<QHelpEvent *>(event);
        const QString text = describeAt(help->pos());
        if (text.isEmpty())
            QToolTip::hideText();
        else
            QToolTip::showText(help->globalPos(), text, viewport());
        return true;
    }
    return QChartView::viewportEvent(event);
}

} // namespace slew::ui
