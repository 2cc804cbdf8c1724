// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The station's horizon mask (core/sky/horizonmask.h) drawn on a polar
// plot: the sky it hides as ground, from the rim up to the mask, and the
// mask's line. The plot, the schedule's pictures and the pass report draw
// it the same way.

#include <QPointF>

#include <functional>

class QPainter;

namespace slew::sky {
class HorizonMask;
}

namespace slew::ui {

// `pointFor` maps an azimuth and an elevation to the plot (elevation 0 at
// the rim, `centre` and `radius` its circle).
void paintHorizonMask(QPainter &p, const sky::HorizonMask &mask, const std::function<QPointF(double, double)> &pointFor,
                      QPointF centre, double radius);

} // namespace slew::ui
