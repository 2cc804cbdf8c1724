// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The plan of the pass a station is waiting for or following, as a face
// draws it: the target's track across the sky and the antenna's planned
// path. Published on a broker as JSON (remote/stationplan.h).

#include <QList>
#include <QPointF>
#include <QString>

#include <optional>

namespace slew::face {

struct StationPlan {
    qint64 unixMs = 0;
    QString target; // empty: no pass ahead
    int norad = 0;  // 0 for the sun, the moon, a fixed direction
    std::optional<qint64> aosMs, tcaMs, losMs;
    std::optional<double> maxElevation;
    std::optional<double> plannedWorstDeg;
    bool flipped = false;
    bool overTheTop = false;
    int unwinds = 0;
    double azimuthTurnStart = 0;  // the rotator's azimuth stop
    double azimuthTurnEnd = 360;  // past this, the overlap
    QList<QPointF> sky;  // the target's az, el, AOS to LOS
    QList<QPointF> path; // the plan's mechanical az, el (el past 90°: the flip)
};

} // namespace slew::face
