// SPDX-License-Identifier: GPL-3.0-or-later
#include "wizard/tuningchart.h"

#include <QChart>
#include <QLineSeries>
#include <QPen>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace slew::ui {

TuningChart::TuningChart(QWidget *parent) : QChartView(parent)
{
    auto *chart = new QChart;
    // Follow the window's theme: the operator window is dark, and a white
    // chart inside it dazzles. The theme goes first; it would repaint the
    // series' pens set below.
    if (palette().color(QPalette::Window).lightness() < 128) {
        chart->setTheme(QChart::ChartThemeDark);
        chart->setBackgroundRoundness(0);
    }
    m_before = new QLineSeries(chart);
    m_before->setName(tr("before"));
    m_before->setPen(QPen(QColor(0xd9, 0x53, 0x4f), 2));
    m_after = new QLineSeries(chart);
    m_after->setName(tr("after"));
    m_after->setPen(QPen(QColor(0x2a, 0x9d, 0x5c), 2));
    m_target = new QLineSeries(chart);
    m_target->setName(tr("target"));
    m_target->setPen(QPen(Qt::gray, 1, Qt::DashLine));
    for (QLineSeries *s : {m_target, m_before, m_after})
        chart->addSeries(s);
    auto *x = new QValueAxis(chart);
    x->setTitleText(tr("time since the step (s)"));
    auto *y = new QValueAxis(chart);
    y->setTitleText(tr("position (°)"));
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    for (QLineSeries *s : {m_target, m_before, m_after}) {
        s->attachAxis(x);
        s->attachAxis(y);
    }
    chart->setTitle(tr("Step response"));
    // The QChartView constructor made a chart of its own; setChart() lets go
    // of it without deleting it (Qt's documented contract), so delete it here.
    QChart *const made = this->chart();
    setChart(chart);
    delete made;
    setRenderHint(QPainter::Antialiasing);
    // Room for the title, the legend, four or five ticks and both axis titles.
    setMinimumSize(360, 260);
}

void TuningChart::clear()
{
    m_before->clear();
    m_after->clear();
    m_target->clear();
}

void TuningChart::fit(double start, double target, double seconds)
{
    const double lo = std::min(start, target), hi = std::max(start, target);
    const double span = std::max(1.0, hi - lo);
    auto *x = qobject_cast<QValueAxis *>(chart()->axes(Qt::Horizontal).value(0));
    auto *y = qobject_cast<QValueAxis *>(chart()->axes(Qt::Vertical).value(0));
    if (x)
        x->setRange(0, std::max(1.0, seconds));
    if (y)
        y->setRange(lo - 0.2 * span, hi + 0.7 * span);
    niceTicks();
    const double end = x ? x->max() : std::max(1.0, seconds);
    m_target->replace({QPointF(0, target), QPointF(end, target)});
}

void TuningChart::addSample(bool after, const tuning::PositionSample &sample)
{
    (after ? m_after : m_before)->append(sample.t, sample.position);
    auto *x = qobject_cast<QValueAxis *>(chart()->axes(Qt::Horizontal).value(0));
    auto *y = qobject_cast<QValueAxis *>(chart()->axes(Qt::Vertical).value(0));
    const bool first = m_before->count() + m_after->count() == 1;
    if (x)
        x->setRange(0, std::max(first ? 1.0 : x->max(), sample.t));
    if (y)
        y->setRange(first ? sample.position - 1 : std::min(y->min(), sample.position - 0.5),
                    first ? sample.position + 1 : std::max(y->max(), sample.position + 0.5));
    niceTicks();
}

void TuningChart::niceTicks()
{
    // Ticks at multiples of 1, 2 or 5 times a power of ten (0.5°, 1 s), about
    // five to an axis, rather than at fifths of whatever the range is
    // (2.45°, 1.3 s). The range itself stays where the data put it.
    for (QAbstractAxis *axis : chart()->axes()) {
        auto *value = qobject_cast<QValueAxis *>(axis);
        if (!value || !(value->max() > value->min()))
            continue;
        const double rough = (value->max() - value->min()) / 5.0;
        const double power = std::pow(10.0, std::floor(std::log10(rough)));
        const double step = power * (rough / power < 1.5 ? 1.0 : rough / power < 3.5 ? 2.0 : 5.0);
        value->setTickType(QValueAxis::TicksDynamic);
        value->setTickAnchor(0.0);
        value->setTickInterval(step);
        const int decimals = std::max(0, int(-std::floor(std::log10(step) + 1e-9)));
        value->setLabelFormat(QStringLiteral("%.%1f").arg(decimals));
    }
}

void TuningChart::showResult(const tuning::TuningResult &r)
{
    auto points = [](const tuning::StepResponse &s) {
        QList<QPointF> p;
        for (const auto &sample : s.samples)
            p.append(QPointF(sample.t, sample.position));
        return p;
    };
    m_before->replace(points(r.before));
    m_after->replace(points(r.after));
    chart()->setTitle(tr("%1 step %2° → %3°")
                          .arg(tuning::axisName(r.axis))
                          .arg(r.before.start, 0, 'f', 1)
                          .arg(r.before.target, 0, 'f', 1));
    fit(r.before.start, r.before.target, std::max(r.before.duration, r.after.duration));
}

} // namespace slew::ui
