#pragma once
// The sky as the antenna sees it: north up, azimuth clockwise, elevation 90°
// at the centre and 0° at the rim. Shows the actual, commanded and target
// positions, a fading trail, the azimuth end stops and overlap, the park
// position, and the station's horizon mask as ground. A click or drag picks a target; the widget only reports it
// (targetPicked) and never moves anything itself.

#include "model/rotatorlimits.h"
#include "rotor/passoverlay.h"

#include <QElapsedTimer>
#include <QPointF>
#include <QWidget>

#include <deque>
#include <memory>
#include <optional>

class QPainter;

namespace slew::sky {
class HorizonMask;
}

namespace slew::ui {

class PolarPlotWidget : public QWidget {
    Q_OBJECT
public:
    static constexpr int kTrailLength = 600; // positions kept for the trail (a minute at 10 Hz)

    explicit PolarPlotWidget(QWidget *parent = nullptr);

    void setLimits(const model::RotatorLimits &limits);
    // Where PARK goes, none while it is not known (the controller's park
    // registers not read yet): no marker rather than a guessed one.
    void setPark(std::optional<QPointF> azEl);
    void setActual(double az, double el, bool stale);
    void setCommanded(double az, double el);
    void setTarget(double az, double el);
    void clearTarget(); // heading for no known target: stopped, or parking where not read yet
    void setPendingTarget(std::optional<QPointF> azEl); // awaiting the operator's confirmation
    void clearPositions();                              // a new connection: forget the old rotator
    // A planned pass to draw (the Tracking tab's selection); none clears it.
    void setPassOverlay(std::optional<PassOverlay> overlay);
    void setPassTarget(std::optional<QPointF> azEl);
    const std::optional<PassOverlay> &passOverlay() const { return m_pass; }
    // What hides the sky at the station (the place's horizon mask); none: flat.
    void setHorizonMask(std::shared_ptr<const sky::HorizonMask> mask);
    const std::shared_ptr<const sky::HorizonMask> &horizonMask() const { return m_horizon; }
    // A small plot among many (the station network) leaves the key out.
    void setLegendShown(bool shown) { m_legendShown = shown; update(); }

    bool isStale() const { return m_stale; }
    std::optional<QPointF> actual() const { return m_actual; }
    std::optional<QPointF> park() const { return m_park; }
    int trailSize() const { return int(m_trail.size()); }

    // Geometry, public so tests can click on a known az/el.
    QPointF pointFor(double az, double el) const;
    std::optional<QPointF> azElAt(const QPointF &pos) const; // none outside the horizon

    QSize sizeHint() const override { return {480, 480}; }
    QSize minimumSizeHint() const override { return {240, 240}; }

signals:
    void targetPicked(double az, double el);

protected:
    void paintEvent(QPaintEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void leaveEvent(QEvent *event) override;

private:
    QPointF centre() const;
    double radius() const;
    void paintGrid(QPainter &p) const;
    void paintTravel(QPainter &p) const;
    void paintTrail(QPainter &p) const;
    void paintMarkers(QPainter &p) const;
    void paintLegend(QPainter &p) const;

    model::RotatorLimits m_limits;
    std::optional<QPointF> m_park, m_actual, m_commanded, m_target, m_pending, m_drag, m_hover;
    bool m_stale = true;
    bool m_legendShown = true;
    std::deque<QPointF> m_trail; // az, el; oldest first
    std::optional<PassOverlay> m_pass;
    std::shared_ptr<const sky::HorizonMask> m_horizon;
};

} // namespace slew::ui
