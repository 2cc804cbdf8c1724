#include "widgets/compassdial.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace slew::ui {
namespace {

// The plot's colours (polarplotwidget.cpp), so the two read alike.
const QColor kFace(0x1a, 0x1f, 0x26);
const QColor kRim(0x3a, 0x42, 0x4e);
const QColor kLabel(0x9a, 0xa5, 0xb4);
const QColor kActual(0x4c, 0xd9, 0x64);
const QColor kTarget(0x3c, 0xb4, 0xf2);
const QColor kStale(0x80, 0x80, 0x80);

// A point `radius` from the centre at a bearing (clockwise from up).
QPointF atBearing(QPointF centre, double radius, double degrees)
{
    const double r = degrees * M_PI / 180.0;
    return centre + QPointF(radius * std::sin(r), -radius * std::cos(r));
}

} // namespace

CompassDial::CompassDial(QWidget *parent) : QWidget(parent)
{
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Preferred);
}

void CompassDial::setHeading(double degrees, bool stale)
{
    m_heading = degrees;
    m_stale = stale;
    update();
}

void CompassDial::setTarget(std::optional<double> degrees)
{
    m_target = degrees;
    update();
}

void CompassDial::clear()
{
    m_heading.reset();
    m_target.reset();
    m_stale = true;
    update();
}

void CompassDial::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const double side = std::min(width(), height()) - 4.0;
    const QPointF centre(width() / 2.0, height() / 2.0);
    const double radius = side / 2.0;

    p.setPen(QPen(kRim, 1.5));
    p.setBrush(kFace);
    p.drawEllipse(centre, radius, radius);
    // Ticks every 30°, longer at the cardinal points; N marked.
    for (int b = 0; b < 360; b += 30) {
        const double inner = radius * (b % 90 == 0 ? 0.78 : 0.88);
        p.drawLine(atBearing(centre, inner, b), atBearing(centre, radius, b));
    }
    QFont f = font();
    f.setPointSizeF(std::max(6.0, radius / 6.0));
    p.setFont(f);
    p.setPen(kLabel);
    const QPointF north = atBearing(centre, radius * 0.58, 0);
    p.drawText(QRectF(north.x() - 10, north.y() - 8, 20, 16), Qt::AlignCenter, QStringLiteral("N"));

    if (m_target) {
        p.setPen(QPen(kTarget, 2));
        p.setBrush(Qt::NoBrush);
        p.drawEllipse(atBearing(centre, radius * 0.88, *m_target), radius * 0.1, radius * 0.1);
    }
    if (m_heading) {
        const QColor needle = m_stale ? kStale : kActual;
        p.setPen(QPen(needle, std::max(2.0, radius / 14.0), Qt::SolidLine, Qt::RoundCap));
        p.drawLine(centre, atBearing(centre, radius * 0.85, *m_heading));
        p.setBrush(needle);
        p.setPen(Qt::NoPen);
        p.drawEllipse(centre, radius * 0.07, radius * 0.07);
    }
}

} // namespace slew::ui
