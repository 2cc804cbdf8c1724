// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A recorded pass on the sky, as the window's polar plot draws the sky:
// north up, azimuth clockwise, the horizon at the rim and the zenith in the
// centre. The target's track (blue) and the antenna's path (green), AOS
// and the end marked, TCA on the track, with a legend. The antenna's
// reading is the rotator's own (an azimuth past 360°, an elevation past
// 90° on a flip): it is drawn where it points on the sky.

#include "records/passrecord.h"

#include <QList>
#include <QRectF>

class QPainter;

namespace slew::ui {

// Paints into `area` (a square fits best). The last point is "LOS" for a
// pass tracked to its end, else "end".
void paintPassSky(QPainter &p, const QRectF &area, const QList<records::PassSample> &samples,
                  const records::PassRecord &record);

} // namespace slew::ui
