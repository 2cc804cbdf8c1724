// SPDX-License-Identifier: GPL-3.0-or-later
#include "axismotion.h"

#include <QList>
#include <QObject>
#include <QPair>

#include <algorithm>
#include <cmath>

namespace slew::tuning {

AxisMotion measureAxisMotion(const StepResponse &step, double band)
{
    AxisMotion m;
    const QList<PositionSample> &s = step.samples;
    const double direction = step.amplitude() >= 0 ? 1.0 : -1.0;
    if (s.size() < 4 || std::abs(step.amplitude()) < 4 * band) {
        m.error = QObject::tr("the step is too short to measure the axis' motion");
        return m;
    }
    // The first movement: the axis has left the start by the band.
    int moving = -1;
    for (int i = 0; i < s.size(); ++i) {
        if (direction * (s[i].position - step.start) > band) {
            moving = i;
            break;
        }
    }
    if (moving < 0) {
        m.error = QObject::tr("the axis did not move");
        return m;
    }
    // When it started: an axis getting up to speed covers a distance that
    // grows with the square of the time, so the square root of the distance
    // grows linearly; the line through the first two moving samples meets
    // zero at the start.
    const int next = std::min(int(s.size()) - 1, moving + 1);
    const double root1 = std::sqrt(std::max(0.0, direction * (s[moving].position - step.start)));
    const double root2 = std::sqrt(std::max(0.0, direction * (s[next].position - step.start)));
    m.responseDelayS = root2 > root1 ? s[moving].t - root1 * (s[next].t - s[moving].t) / (root2 - root1) : s[moving].t;
    m.responseDelayS = std::clamp(m.responseDelayS, 0.0, s[moving].t);

    // The speed: the steepest average slope over kSpeedWindowS, and only if
    // the axis held it (within 10 %) for kSpeedHeldS: a short step ends
    // while the axis is still getting up to speed, and its steepest slope
    // is not the axis' speed.
    QList<QPair<double, double>> rates; // (start time, rate over the window)
    for (int i = moving; i < s.size(); ++i) {
        int j = i;
        while (j < s.size() && s[j].t - s[i].t < kSpeedWindowS)
            ++j;
        if (j >= s.size())
            break;
        const double rate = direction * (s[j].position - s[i].position) / (s[j].t - s[i].t);
        rates.append({s[i].t, rate});
        m.speedDegS = std::max(m.speedDegS, rate);
    }
    double heldFrom = -1, heldTo = -1;
    for (const auto &[t, rate] : rates) {
        if (rate < 0.9 * m.speedDegS)
            continue;
        heldFrom = heldFrom < 0 ? t : heldFrom;
        heldTo = t + kSpeedWindowS;
    }
    if (!(m.speedDegS > 0) || heldTo - heldFrom < kSpeedHeldS) {
        m.error = QObject::tr("the step was too short for the axis to reach its full speed; 20° or more is long enough");
        m.speedDegS = 0;
        return m;
    }
    // The speed it held: the median of the windows near the top, so one
    // window stretched by a late reading does not pass for the speed.
    QList<double> held;
    for (const auto &[t, rate] : rates)
        if (rate >= 0.9 * m.speedDegS)
            held.append(rate);
    std::sort(held.begin(), held.end());
    m.speedDegS = held[held.size() / 2];
    // Acceleration: how long from the first movement until the local rate
    // (over one sample) first reaches 90 % of that speed.
    for (int i = moving; i + 1 < s.size(); ++i) {
        const double rate = direction * (s[i + 1].position - s[i].position) / (s[i + 1].t - s[i].t);
        if (rate >= 0.9 * m.speedDegS) {
            const double rampS = 0.5 * (s[i].t + s[i + 1].t) - m.responseDelayS;
            m.accelDegS2 = rampS > 0.02 ? 0.9 * m.speedDegS / rampS : 0.0; // 0: at once, as the planner reads it
            break;
        }
    }
    m.ok = true;
    return m;
}

} // namespace slew::tuning
