#include "rotor/passoverlay.h"

#include <QObject>
#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace slew::ui {
namespace {

const QColor kSkyTrack(0x3c, 0xb4, 0xf2);   // the plot's target blue
const QColor kPlanned(0xf2, 0xc0, 0x3c);    // the plot's commanded amber
const QColor kOverlap(0xf2, 0x9a, 0x3c);
const QColor kLabel(0x9a, 0xa5, 0xb4);

void label(QPainter &p, const QPointF &at, const QString &text, const QColor &colour)
{
    p.setPen(colour);
    p.drawText(at + QPointF(8, -6), text);
}

// A label for a point on the horizon (AOS, LOS), set inside the circle
// towards the zenith: outside it, it sat on the bearings' numbers and
// letters ("LOS" on "E").
void labelInside(QPainter &p, const QPointF &at, const QPointF &zenith, const QString &text, const QColor &colour)
{
    const QPointF towards = zenith - at;
    const double length = std::hypot(towards.x(), towards.y());
    if (length < 30.0) {
        label(p, at, text, colour);
        return;
    }
    const QPointF middle = at + towards * (16.0 / length);
    const QFontMetricsF metrics(p.font());
    const QSizeF size(metrics.horizontalAdvance(text) + 2, metrics.height());
    p.setPen(colour);
    p.drawText(QRectF(middle - QPointF(size.width() / 2, size.height() / 2), size), Qt::AlignCenter, text);
}

} // namespace

void paintPassOverlay(QPainter &p, const PassOverlay &o, const std::function<QPointF(double, double)> &pointFor)
{
    if (o.sky.size() < 2)
        return;
    QColor track = kSkyTrack;
    track.setAlphaF(0.55f);
    p.setPen(QPen(track, 2));
    for (int i = 1; i < o.sky.size(); ++i)
        p.drawLine(pointFor(o.sky[i - 1].x(), o.sky[i - 1].y()), pointFor(o.sky[i].x(), o.sky[i].y()));

    std::optional<QPointF> overlapAt, unwindAt;
    for (int i = 1; i < o.planned.size(); ++i) {
        const QPointF &a = o.planned[i - 1], &b = o.planned[i];
        if (std::abs(b.x() - a.x()) > 180.0) { // an unwind: no line across the sky
            unwindAt = b;
            continue;
        }
        const bool overlap = b.x() > o.azimuthTurnEnd || b.x() < o.azimuthTurnStart;
        if (overlap && !overlapAt)
            overlapAt = b;
        p.setPen(QPen(overlap ? kOverlap : kPlanned, 1.5, Qt::DotLine));
        p.drawLine(pointFor(a.x(), a.y()), pointFor(b.x(), b.y()));
    }
    QFont f = p.font();
    f.setPointSizeF(f.pointSizeF() * 0.85);
    p.setFont(f);
    const QPointF aos = pointFor(o.sky.front().x(), o.sky.front().y());
    const QPointF los = pointFor(o.sky.back().x(), o.sky.back().y());
    p.setPen(QPen(kSkyTrack, 2));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(aos, 4, 4);
    p.drawRect(QRectF(los.x() - 4, los.y() - 4, 8, 8));
    const QPointF zenith = pointFor(0.0, 90.0);
    labelInside(p, aos, zenith, QObject::tr("AOS"), kLabel);
    labelInside(p, los, zenith, QObject::tr("LOS"), kLabel);
    if (overlapAt)
        label(p, pointFor(overlapAt->x(), overlapAt->y()), QObject::tr("overlap"), kOverlap);
    if (unwindAt)
        label(p, pointFor(unwindAt->x(), unwindAt->y()), QObject::tr("unwind"), QColor(0xe5, 0x48, 0x48));
    if (o.overTheTop && !o.planned.isEmpty()) {
        const auto top = std::min_element(o.planned.begin(), o.planned.end(), [](const QPointF &a, const QPointF &b) {
            return std::abs(a.y() - 90.0) < std::abs(b.y() - 90.0);
        });
        label(p, pointFor(top->x(), top->y()), QObject::tr("over the top"), kPlanned);
    } else if (o.flipped && !o.planned.isEmpty()) {
        const QPointF mid = o.planned[o.planned.size() / 2];
        label(p, pointFor(mid.x(), mid.y()), QObject::tr("flip"), kPlanned);
    }
    if (o.targetNow) {
        p.setPen(Qt::NoPen);
        p.setBrush(kSkyTrack);
        p.drawEllipse(pointFor(o.targetNow->x(), o.targetNow->y()), 5, 5);
    }
}

} // namespace slew::ui
