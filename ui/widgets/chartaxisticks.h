// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where a chart's value axis puts its ticks when its labels are whole
// numbers: a step of 1, 2 or 5 times a power of ten, never below 1, so no
// two labels print the same number (25, 25, 26 from half-degree steps); as
// many ticks as the chart's height has room for; and a flat series (a
// rotator at rest) gets one step either side instead of a range so thin
// that its labels cannot be drawn. Pure: no Qt Charts in here.

namespace slew::ui {

// The axis shows min..max; ticks (and labels) stand at every multiple of
// step in it, the first at firstTick.
struct AxisTicks {
    double min = 0.0;
    double max = 1.0;
    double step = 1.0;
    double firstTick = 0.0;
    int count = 2;
};

// lo..hi is the data's range (lo > hi when there is no data); maxTicks the
// most ticks that fit, at least 2.
AxisTicks wholeNumberTicks(double lo, double hi, int maxTicks);

// How many ticks a vertical axis of this many pixels has room for.
int ticksForHeight(double pixels);

} // namespace slew::ui
