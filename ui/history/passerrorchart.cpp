// SPDX-License-Identifier: GPL-3.0-or-later
#include "history/passerrorchart.h"

#include "tracking/tracker.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace slew::ui {
namespace {

const QColor kPlot(0x1a, 0x1f, 0x26);
const QColor kGrid(0x3a, 0x42, 0x4e);
const QColor kLabel(0x9a, 0xa5, 0xb4);
const QColor kError(0xf2, 0xc0, 0x3c);   // the telemetry chart's pointing error
const QColor kMarker(0xdc, 0xe2, 0xea);
const QColor kPlanned(0xf2, 0x9a, 0x3c);
// The tracker's figures leave out the same first seconds.
constexpr qint64 kSettleMs = qint64(tracking::Tracker::kSettleSeconds * 1000);

QString number(double value, double step)
{
    const int decimals = step >= 1 ? 0 : std::min(3, int(std::ceil(-std::log10(step))));
    return QString::number(value, 'f', decimals);
}

} // namespace

double niceStep(double span, int maxSteps)
{
    if (!(span > 0) || maxSteps < 1)
        return 1.0;
    const double raw = span / maxSteps;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0}) {
        if (m * power >= raw)
            return m * power;
    }
    return 10.0 * power;
}

void paintPassError(QPainter &p, const QRectF &area, const QList<records::PassSample> &samples,
                    const records::PassRecord &record)
{
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    const QFontMetricsF metrics(p.font());
    const QRectF plot = area.adjusted(58, 44, -16, -42);
    p.fillRect(plot, kPlot);

    // Minutes from AOS: from AOS (or the first sample, if earlier) to LOS
    // (or the last sample, if later).
    const qint64 aosMs = record.planned.aos.toMSecsSinceEpoch();
    auto minutes = [aosMs](qint64 ms) { return double(ms - aosMs) / 60000.0; };
    double x0 = 0, x1 = record.planned.los.isValid() ? minutes(record.planned.los.toMSecsSinceEpoch()) : 0;
    // The scale is set by the error once the antenna has settled on the
    // pass (the tracker's figures start then too): a late start's first
    // seconds of catching up would flatten the rest into the axis.
    double worst = 0, settling = 0;
    const qint64 settledMs = samples.isEmpty() ? 0 : samples.first().unixMs + kSettleMs;
    for (const records::PassSample &s : samples) {
        x0 = std::min(x0, minutes(s.unixMs));
        x1 = std::max(x1, minutes(s.unixMs));
        if (s.unixMs >= settledMs)
            worst = std::max(worst, s.errorDeg);
        else
            settling = std::max(settling, s.errorDeg);
    }
    if (record.planned.plannedWorstDeg)
        worst = std::max(worst, *record.planned.plannedWorstDeg);
    if (x1 - x0 < 0.5)
        x1 = x0 + 0.5;
    const double yStep = niceStep(std::max(worst, 0.1) * 1.1, 5);
    const double y1 = std::ceil(std::max(worst, 0.1) * 1.1 / yStep) * yStep;
    auto X = [&](double m) { return plot.left() + (m - x0) / (x1 - x0) * plot.width(); };
    auto Y = [&](double deg) { return plot.bottom() - deg / y1 * plot.height(); };

    // Grid and labels.
    p.setPen(QPen(kGrid, 1));
    const double xStep = niceStep(x1 - x0, 10);
    for (double m = std::ceil(x0 / xStep) * xStep; m <= x1 + 1e-9; m += xStep) {
        p.setPen(QPen(kGrid, 1));
        p.drawLine(QPointF(X(m), plot.top()), QPointF(X(m), plot.bottom()));
        p.setPen(kLabel);
        p.drawText(QRectF(X(m) - 30, plot.bottom() + 4, 60, 18), Qt::AlignHCenter | Qt::AlignTop, number(m, xStep));
    }
    for (double d = 0; d <= y1 + 1e-9; d += yStep) {
        p.setPen(QPen(kGrid, 1));
        p.drawLine(QPointF(plot.left(), Y(d)), QPointF(plot.right(), Y(d)));
        p.setPen(kLabel);
        p.drawText(QRectF(area.left(), Y(d) - 9, 52, 18), Qt::AlignRight | Qt::AlignVCenter, number(d, yStep));
    }
    p.setPen(kLabel);
    p.drawText(QRectF(plot.left(), plot.bottom() + 22, plot.width(), 18), Qt::AlignHCenter | Qt::AlignTop,
               QObject::tr("minutes from AOS"));
    p.drawText(QRectF(area.left(), area.top(), area.width(), 20), Qt::AlignLeft | Qt::AlignVCenter,
               QObject::tr("Pointing error (° on the sky)"));

    // The plan's worst, for comparison.
    if (record.planned.plannedWorstDeg) {
        const double y = Y(*record.planned.plannedWorstDeg);
        p.setPen(QPen(kPlanned, 1.5, Qt::DashLine));
        p.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
        const QString text = QObject::tr("planned worst %1°").arg(*record.planned.plannedWorstDeg, 0, 'f', 2);
        p.setPen(kPlanned);
        p.drawText(QPointF(plot.right() - metrics.horizontalAdvance(text) - 6, y - 5), text);
    }

    // AOS, TCA and LOS.
    const struct {
        QDateTime at;
        QString name;
    } marks[] = {{record.planned.aos, QObject::tr("AOS")},
                 {record.planned.tca, QObject::tr("TCA")},
                 {record.planned.los, QObject::tr("LOS")}};
    for (const auto &m : marks) {
        if (!m.at.isValid())
            continue;
        const double x = X(minutes(m.at.toMSecsSinceEpoch()));
        if (x < plot.left() - 0.5 || x > plot.right() + 0.5)
            continue;
        p.setPen(QPen(kMarker, 1.5, Qt::DotLine));
        p.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
        p.setPen(kMarker);
        const double w = metrics.horizontalAdvance(m.name);
        const double left = std::clamp(x - w / 2, plot.left(), plot.right() - w);
        p.drawText(QPointF(left, plot.top() - 5), m.name);
    }

    // The error, broken where the samples have a gap of over ten seconds.
    QPainterPath path;
    for (qsizetype i = 0; i < samples.size(); ++i) {
        const QPointF at(X(minutes(samples[i].unixMs)), Y(samples[i].errorDeg));
        if (i == 0 || samples[i].unixMs - samples[i - 1].unixMs > 10000)
            path.moveTo(at);
        else
            path.lineTo(at);
    }
    p.setClipRect(plot.adjusted(-1, -1, 1, 1));
    p.setPen(QPen(kError, 1.6));
    p.setBrush(Qt::NoBrush);
    p.drawPath(path);
    p.setClipping(false);
    p.setPen(QPen(kGrid, 1));
    p.drawRect(plot);
    if (settling > y1) {
        p.setPen(kError);
        p.drawText(QPointF(plot.left() + 8, plot.top() + metrics.ascent() + 4),
                   QObject::tr("↑ off the scale: up to %1° in the first %2 s, while the antenna caught up")
                       .arg(settling, 0, 'f', 1)
                       .arg(kSettleMs / 1000));
    }
    p.restore();
}

} // namespace slew::ui
