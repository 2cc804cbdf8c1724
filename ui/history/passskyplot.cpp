// SPDX-License-Identifier: GPL-3.0-or-later
#include "history/passskyplot.h"

#include <QPainter>
#include <QPainterPath>

#include <cmath>
#include <numbers>

namespace slew::ui {
namespace {

// The window's plot colours (polarplotwidget.cpp).
const QColor kDisc(0x1a, 0x1f, 0x26);
const QColor kGrid(0x3a, 0x42, 0x4e);
const QColor kLabel(0x9a, 0xa5, 0xb4);
const QColor kAntenna(0x4c, 0xd9, 0x64);
const QColor kTarget(0x3c, 0xb4, 0xf2);
const QColor kMark(0xdc, 0xe2, 0xea);

struct Sky {
    QPointF centre;
    double radius;
    // Where an az, el of the sky is drawn; an elevation past 90° looks
    // back over the zenith.
    QPointF at(double az, double el) const
    {
        if (el > 90.0) {
            el = 180.0 - el;
            az += 180.0;
        }
        const double r = radius * (90.0 - std::clamp(el, 0.0, 90.0)) / 90.0;
        const double a = az * std::numbers::pi / 180.0;
        return centre + QPointF(r * std::sin(a), -r * std::cos(a));
    }
};

void paintGrid(QPainter &p, const Sky &sky)
{
    p.setPen(QPen(kGrid, 1));
    p.setBrush(kDisc);
    p.drawEllipse(sky.centre, sky.radius, sky.radius);
    p.setBrush(Qt::NoBrush);
    for (int el : {30, 60})
        p.drawEllipse(sky.centre, sky.radius * (90 - el) / 90.0, sky.radius * (90 - el) / 90.0);
    for (int az = 0; az < 360; az += 30)
        p.drawLine(sky.centre, sky.at(az, 0));
    p.setPen(kLabel);
    // The rim is the horizon; a "0°" there sat under many a pass's AOS.
    for (int el : {30, 60})
        p.drawText(sky.at(15, el) + QPointF(2, 14), QStringLiteral("%1°").arg(el));
    const char *cardinal[] = {"N", "E", "S", "W"};
    for (int az = 0; az < 360; az += 30) {
        const double a = az * std::numbers::pi / 180.0;
        const QPointF at = sky.centre + QPointF((sky.radius + 16) * std::sin(a), -(sky.radius + 16) * std::cos(a));
        const QString text = az % 90 == 0 ? QString::fromLatin1(cardinal[az / 90]) : QString::number(az);
        p.drawText(QRectF(at.x() - 22, at.y() - 10, 44, 20), Qt::AlignCenter, text);
    }
}

// A line through the points, broken where two neighbours are more than a
// quarter of the disc apart (an unwind, or a gap in the samples), so no
// chord is drawn across the sky that the antenna never swept.
QPainterPath pathOf(const QList<QPointF> &points, double radius)
{
    QPainterPath path;
    for (int i = 0; i < points.size(); ++i) {
        if (i == 0 || QLineF(points[i - 1], points[i]).length() > radius / 2)
            path.moveTo(points[i]);
        else
            path.lineTo(points[i]);
    }
    return path;
}

void mark(QPainter &p, const QPointF &at, const QString &text, const QColor &colour)
{
    p.setPen(QPen(colour, 2));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(at, 6, 6);
    p.setPen(kMark);
    p.drawText(at + QPointF(9, -7), text);
}

void paintLegend(QPainter &p, const QRectF &area)
{
    const struct {
        QColor colour;
        QString text;
    } entries[] = {{kTarget, QObject::tr("target's track")}, {kAntenna, QObject::tr("antenna's path")}};
    double y = area.top() + 14;
    for (const auto &e : entries) {
        p.setPen(QPen(e.colour, 3));
        p.drawLine(QPointF(area.left() + 4, y), QPointF(area.left() + 24, y));
        p.setPen(kLabel);
        p.drawText(QPointF(area.left() + 30, y + 5), e.text);
        y += 20;
    }
}

} // namespace

void paintPassSky(QPainter &p, const QRectF &area, const QList<records::PassSample> &samples,
                  const records::PassRecord &record)
{
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    const Sky sky{area.center(), std::max(10.0, std::min(area.width(), area.height()) / 2.0 - 34.0)};
    paintGrid(p, sky);
    QList<QPointF> target, antenna;
    for (const records::PassSample &s : samples) {
        target.append(sky.at(s.targetAzDeg, s.targetElDeg));
        antenna.append(sky.at(s.antennaAzDeg, s.antennaElDeg));
    }
    p.setBrush(Qt::NoBrush);
    // A wide, half-seen band under the antenna's line: where they agree
    // both show.
    QColor band = kTarget;
    band.setAlphaF(0.6f);
    p.setPen(QPen(band, 6, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    p.drawPath(pathOf(target, sky.radius));
    p.setPen(QPen(kAntenna, 2, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    p.drawPath(pathOf(antenna, sky.radius));
    if (!samples.isEmpty()) {
        mark(p, target.first(), QObject::tr("AOS"), kTarget);
        mark(p, target.last(),
             record.outcome == records::Outcome::Tracked ? QObject::tr("LOS") : QObject::tr("end"), kTarget);
        // TCA: the sample nearest the highest point, when the pass got there.
        const qint64 tca = record.planned.tca.isValid() ? record.planned.tca.toMSecsSinceEpoch() : 0;
        if (tca >= samples.first().unixMs && tca <= samples.last().unixMs) {
            qsizetype nearest = 0;
            for (qsizetype i = 1; i < samples.size(); ++i) {
                if (std::llabs(samples[i].unixMs - tca) < std::llabs(samples[nearest].unixMs - tca))
                    nearest = i;
            }
            mark(p, target[nearest], QObject::tr("TCA"), kTarget);
        }
    }
    paintLegend(p, area);
    p.restore();
}

} // namespace slew::ui
