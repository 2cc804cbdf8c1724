#include "rotor/polarplotwidget.h"

#include "rotor/horizonpainter.h"

#include "sky/horizonmask.h"

#include <QMouseEvent>
#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>

#include <cmath>
#include <numbers>

namespace slew::ui {

namespace {

constexpr double kMargin = 30.0;
const QColor kBackground(0x14, 0x17, 0x1c);
const QColor kGrid(0x3a, 0x42, 0x4e);
const QColor kLabel(0x9a, 0xa5, 0xb4);
const QColor kActual(0x4c, 0xd9, 0x64);
const QColor kCommanded(0xf2, 0xc0, 0x3c);
const QColor kTarget(0x3c, 0xb4, 0xf2);
const QColor kStop(0xe5, 0x48, 0x48);
const QColor kOverlap(0xf2, 0x9a, 0x3c);
const QColor kStale(0x80, 0x80, 0x80);

double radians(double deg) { return deg * std::numbers::pi / 180.0; }

QString azElText(double az, double el)
{
    return QStringLiteral("Az %1°  El %2°").arg(az, 0, 'f', 1).arg(el, 0, 'f', 1);
}

} // namespace

PolarPlotWidget::PolarPlotWidget(QWidget *parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("polarPlot"));
    setMouseTracking(true);
    setCursor(Qt::CrossCursor);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setToolTip(tr("Click or drag to pick a target"));
}

void PolarPlotWidget::setLimits(const model::RotatorLimits &limits)
{
    m_limits = limits;
    update();
}

void PolarPlotWidget::setPark(std::optional<QPointF> azEl)
{
    m_park = azEl;
    update();
}

void PolarPlotWidget::setActual(double az, double el, bool stale)
{
    if (!std::isfinite(az) || !std::isfinite(el))
        return;
    const QPointF p(az, el);
    if (!stale && (m_trail.empty() || m_trail.back() != p)) {
        m_trail.push_back(p);
        while (m_trail.size() > size_t(kTrailLength))
            m_trail.pop_front();
    }
    m_actual = p;
    m_stale = stale;
    update();
}

void PolarPlotWidget::setCommanded(double az, double el)
{
    if (std::isfinite(az) && std::isfinite(el)) {
        m_commanded = QPointF(az, el);
        update();
    }
}

void PolarPlotWidget::setTarget(double az, double el)
{
    if (std::isfinite(az) && std::isfinite(el)) {
        m_target = QPointF(az, el);
        update();
    }
}

void PolarPlotWidget::clearTarget()
{
    m_target.reset();
    update();
}

void PolarPlotWidget::setPendingTarget(std::optional<QPointF> azEl)
{
    m_pending = azEl;
    update();
}

void PolarPlotWidget::clearPositions()
{
    m_actual.reset();
    m_commanded.reset();
    m_target.reset();
    m_pending.reset();
    m_trail.clear();
    m_stale = true;
    update();
}

void PolarPlotWidget::setPassOverlay(std::optional<PassOverlay> overlay)
{
    m_pass = std::move(overlay);
    update();
}

void PolarPlotWidget::setPassTarget(std::optional<QPointF> azEl)
{
    if (!m_pass)
        return;
    m_pass->targetNow = azEl;
    update();
}

QPointF PolarPlotWidget::centre() const
{
    return QPointF(width() / 2.0, height() / 2.0);
}

double PolarPlotWidget::radius() const
{
    return std::max(10.0, std::min(width(), height()) / 2.0 - kMargin);
}

QPointF PolarPlotWidget::pointFor(double az, double el) const
{
    // Past the zenith (elevation up to 180°) the antenna looks the other way.
    if (el > 90.0) {
        el = 180.0 - el;
        az += 180.0;
    }
    const double r = radius() * (90.0 - std::clamp(el, 0.0, 90.0)) / 90.0;
    const double a = radians(az);
    return centre() + QPointF(r * std::sin(a), -r * std::cos(a));
}

void PolarPlotWidget::setHorizonMask(std::shared_ptr<const sky::HorizonMask> mask)
{
    m_horizon = std::move(mask);
    update();
}

std::optional<QPointF> PolarPlotWidget::azElAt(const QPointF &pos) const
{
    const QPointF d = pos - centre();
    const double r = std::hypot(d.x(), d.y());
    if (r > radius() + 1.0)
        return std::nullopt;
    double az = std::atan2(d.x(), -d.y()) * 180.0 / std::numbers::pi;
    if (az < 0)
        az += 360.0;
    const double el = std::max(0.0, 90.0 * (1.0 - r / radius()));
    return QPointF(std::round(az * 10) / 10, std::round(el * 10) / 10);
}

void PolarPlotWidget::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), kBackground);
    paintGrid(p);
    if (m_horizon)
        paintHorizonMask(p, *m_horizon, [this](double az, double el) { return pointFor(az, el); }, centre(), radius());
    paintTravel(p);
    if (m_pass)
        paintPassOverlay(p, *m_pass, [this](double az, double el) { return pointFor(az, el); });
    paintTrail(p);
    paintMarkers(p);
    if (m_legendShown)
        paintLegend(p);
}

void PolarPlotWidget::paintGrid(QPainter &p) const
{
    const QPointF c = centre();
    const double R = radius();
    p.setPen(QPen(kGrid, 1));
    p.setBrush(QColor(0x1a, 0x1f, 0x26));
    p.drawEllipse(c, R, R);
    p.setBrush(Qt::NoBrush);
    for (int el : {30, 60}) {
        const double r = R * (90 - el) / 90.0;
        p.drawEllipse(c, r, r);
    }
    for (int az = 0; az < 360; az += 30) {
        p.drawLine(c, pointFor(az, 0));
    }
    QFont f = font();
    f.setPointSizeF(f.pointSizeF() * 0.85);
    p.setFont(f);
    p.setPen(kLabel);
    // The rings' elevations along bearing 15°, just inside each ring: at
    // north they sat under the antenna's marker when it rests at 0°.
    for (int el : {0, 30, 60}) {
        p.drawText(pointFor(15, el) + QPointF(2, 12), QStringLiteral("%1°").arg(el));
    }
    const char *cardinal[] = {"N", "E", "S", "W"};
    for (int az = 0; az < 360; az += 30) {
        const double a = radians(az);
        const QPointF at = c + QPointF((R + 15) * std::sin(a), -(R + 15) * std::cos(a));
        const QString text = az % 90 == 0 ? QString::fromLatin1(cardinal[az / 90]) : QString::number(az);
        QRectF box(at.x() - 20, at.y() - 9, 40, 18);
        p.drawText(box, Qt::AlignCenter, text);
    }
}

void PolarPlotWidget::paintTravel(QPainter &p) const
{
    const QPointF c = centre();
    const double R = radius();
    const QRectF rim(c.x() - R - 4, c.y() - R - 4, 2 * (R + 4), 2 * (R + 4));
    // Qt angles: 0 at three o'clock, counter-clockwise, in 1/16°.
    auto qtAngle = [](double az) { return int(std::lround((90.0 - az) * 16)); };
    if (m_limits.azMax - m_limits.azMin > 360.0) {
        // Bearings reachable twice: from azMin + 360 to azMax.
        const double from = m_limits.azMin + 360.0, span = m_limits.azMax - from;
        p.setPen(QPen(kOverlap, 6, Qt::SolidLine, Qt::FlatCap));
        p.drawArc(rim, qtAngle(from), -int(std::lround(span * 16)));
    } else if (m_limits.azMax - m_limits.azMin < 360.0) {
        // Bearings that cannot be reached at all.
        p.setPen(QPen(kStop.darker(160), 6, Qt::SolidLine, Qt::FlatCap));
        p.drawArc(rim, qtAngle(m_limits.azMax), -int(std::lround((360.0 - (m_limits.azMax - m_limits.azMin)) * 16)));
    }
    p.setPen(QPen(kStop, 3));
    for (double stop : {m_limits.azMin, m_limits.azMax}) {
        const double a = radians(stop);
        const QPointF dir(std::sin(a), -std::cos(a));
        p.drawLine(c + dir * (R - 10), c + dir * (R + 8));
    }
}

void PolarPlotWidget::paintTrail(QPainter &p) const
{
    if (m_trail.size() < 2)
        return;
    const QColor base = m_stale ? kStale : kActual;
    const double n = double(m_trail.size());
    for (size_t i = 1; i < m_trail.size(); ++i) {
        QColor col = base;
        col.setAlphaF(float(0.08 + 0.6 * (double(i) / n))); // older is fainter
        p.setPen(QPen(col, 2, Qt::SolidLine, Qt::RoundCap));
        p.drawLine(pointFor(m_trail[i - 1].x(), m_trail[i - 1].y()), pointFor(m_trail[i].x(), m_trail[i].y()));
    }
}

void PolarPlotWidget::paintMarkers(QPainter &p) const
{
    if (m_park) {
        const QPointF at = pointFor(m_park->x(), m_park->y());
        p.setPen(QPen(kLabel, 1.5));
        p.setBrush(Qt::NoBrush);
        p.drawRect(QRectF(at.x() - 6, at.y() - 6, 12, 12));
        p.drawText(QRectF(at.x() - 6, at.y() - 6, 12, 12), Qt::AlignCenter, QStringLiteral("P"));
    }
    if (m_target) {
        const QPointF at = pointFor(m_target->x(), m_target->y());
        p.setPen(QPen(kTarget, 2));
        p.setBrush(Qt::NoBrush);
        p.drawEllipse(at, 9, 9);
        p.drawLine(at + QPointF(-14, 0), at + QPointF(-5, 0));
        p.drawLine(at + QPointF(5, 0), at + QPointF(14, 0));
        p.drawLine(at + QPointF(0, -14), at + QPointF(0, -5));
        p.drawLine(at + QPointF(0, 5), at + QPointF(0, 14));
    }
    for (const auto &pending : {m_pending, m_drag}) {
        if (!pending)
            continue;
        const QPointF at = pointFor(pending->x(), pending->y());
        p.setPen(QPen(kTarget, 1.5, Qt::DashLine));
        p.setBrush(Qt::NoBrush);
        p.drawEllipse(at, 12, 12);
    }
    if (m_commanded) {
        const QPointF at = pointFor(m_commanded->x(), m_commanded->y());
        QPainterPath diamond;
        diamond.moveTo(at + QPointF(0, -8));
        diamond.lineTo(at + QPointF(8, 0));
        diamond.lineTo(at + QPointF(0, 8));
        diamond.lineTo(at + QPointF(-8, 0));
        diamond.closeSubpath();
        p.setPen(QPen(kCommanded, 2));
        p.setBrush(Qt::NoBrush);
        p.drawPath(diamond);
    }
    if (m_actual) {
        const QColor col = m_stale ? kStale : kActual;
        const QPointF at = pointFor(m_actual->x(), m_actual->y());
        QColor beam = col;
        beam.setAlphaF(0.5f);
        p.setPen(QPen(beam, 1.5, Qt::DotLine));
        p.drawLine(centre(), at);
        p.setPen(QPen(col.darker(150), 1.5));
        p.setBrush(col);
        p.drawEllipse(at, 7, 7);
        if (m_stale) {
            // Towards the zenith, clear of the marker: beside it, at a low
            // elevation, it sat on the bearings' numbers ("STALE" on "120").
            const QPointF towards = centre() - at;
            const double length = std::hypot(towards.x(), towards.y());
            const QString text = tr("STALE");
            const QFontMetricsF metrics(p.font());
            const QSizeF size(metrics.horizontalAdvance(text) + 2, metrics.height());
            const QPointF middle = length < 40.0 ? at + QPointF(size.width() / 2 + 10, -8)
                                                 : at + towards * ((size.width() / 2 + 12) / length);
            p.setPen(kStale);
            p.drawText(QRectF(middle - QPointF(size.width() / 2, size.height() / 2), size), Qt::AlignCenter, text);
        }
    }
}

void PolarPlotWidget::paintLegend(QPainter &p) const
{
    struct Entry {
        QColor colour;
        QString text;
    };
    const Entry entries[] = {{m_stale ? kStale : kActual, tr("actual")}, {kCommanded, tr("commanded")},
                             {kTarget, tr("target")}, {kStop, tr("end stop")}, {kOverlap, tr("overlap")}};
    QFont f = font();
    f.setPointSizeF(f.pointSizeF() * 0.85);
    p.setFont(f);
    double y = 12;
    for (const Entry &e : entries) {
        p.setPen(Qt::NoPen);
        p.setBrush(e.colour);
        p.drawRoundedRect(QRectF(8, y - 5, 10, 10), 2, 2);
        p.setPen(kLabel);
        p.drawText(QPointF(24, y + 4), e.text);
        y += 16;
    }
    if (m_hover) {
        p.setPen(kLabel);
        p.drawText(QRectF(0, height() - 20, width() - 8, 18), Qt::AlignRight | Qt::AlignVCenter,
                   azElText(m_hover->x(), m_hover->y()));
    }
}

void PolarPlotWidget::mousePressEvent(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton)
        return QWidget::mousePressEvent(event);
    m_drag = azElAt(event->position());
    update();
}

void PolarPlotWidget::mouseMoveEvent(QMouseEvent *event)
{
    m_hover = azElAt(event->position());
    if (m_hover)
        QToolTip::showText(event->globalPosition().toPoint(), azElText(m_hover->x(), m_hover->y()), this);
    else
        QToolTip::hideText();
    if (event->buttons() & Qt::LeftButton)
        m_drag = m_hover;
    update();
}

void PolarPlotWidget::mouseReleaseEvent(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton)
        return QWidget::mouseReleaseEvent(event);
    const auto picked = azElAt(event->position());
    m_drag.reset();
    update();
    if (picked)
        emit targetPicked(picked->x(), picked->y());
}

void PolarPlotWidget::leaveEvent(QEvent *event)
{
    m_hover.reset();
    update();
    QWidget::leaveEvent(event);
}

} // namespace slew::ui
