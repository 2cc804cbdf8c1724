#pragma once
// A planned pass drawn on the polar plot: where the satellite will be (the
// sky track), where the plan points the antenna (dotted; orange where it
// runs in the overlap, and marked where it flips or unwinds), the AOS and
// LOS points, and the target's place on the track now.

#include <QList>
#include <QPointF>
#include <QString>

#include <functional>
#include <optional>

class QPainter;

namespace slew::ui {

struct PassOverlay {
    QList<QPointF> sky;      // az, el of the target, AOS to LOS
    QList<QPointF> planned;  // the plan's mechanical az, el (el past 90° is the flip)
    double azimuthTurnEnd = 360.0; // azimuth positions past this are the overlap
    double azimuthTurnStart = 0.0; // and below this, a south stop's other side
    bool flipped = false;
    bool overTheTop = false; // the planned path crosses the zenith: marked where it does
    int unwinds = 0;
    std::optional<QPointF> targetNow; // az, el
};

// Paints `overlay`; `pointFor` maps an az, el (el up to 180°) to the widget.
void paintPassOverlay(QPainter &p, const PassOverlay &overlay, const std::function<QPointF(double, double)> &pointFor);

} // namespace slew::ui
