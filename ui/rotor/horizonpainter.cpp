// SPDX-License-Identifier: GPL-3.0-or-later
#include "rotor/horizonpainter.h"

#include "sky/horizonmask.h"

#include <QPainter>
#include <QPainterPath>
#include <QPolygonF>

#include <algorithm>

namespace slew::ui {

namespace {

const QColor kGround(0x8a, 0x6a, 0x3e, 90);
const QColor kMaskLine(0xc8, 0x9a, 0x5a);

} // namespace

void paintHorizonMask(QPainter &p, const sky::HorizonMask &mask, const std::function<QPointF(double, double)> &pointFor,
                      QPointF centre, double radius)
{
    if (mask.highestDeg() <= 0)
        return; // nothing above the rim to show
    // The mask's line: every degree, and a wall's foot and top where it stands.
    QPolygonF line;
    qsizetype next = 0;
    const QList<sky::HorizonPoint> &points = mask.points();
    for (int az = 0; az <= 360; ++az) {
        while (next < points.size() && points[next].azimuthDeg < az) {
            line << pointFor(points[next].azimuthDeg, std::max(0.0, points[next].elevationDeg));
            ++next;
        }
        line << pointFor(az, std::max(0.0, mask.elevationAt(az)));
    }
    QPainterPath rim;
    rim.addEllipse(centre, radius, radius);
    QPainterPath sky;
    sky.addPolygon(line);
    sky.closeSubpath();
    p.save();
    p.setPen(Qt::NoPen);
    p.setBrush(kGround);
    p.drawPath(rim.subtracted(sky));
    p.setPen(QPen(kMaskLine, 1.5));
    p.setBrush(Qt::NoBrush);
    p.drawPolyline(line);
    p.restore();
}

} // namespace slew::ui
