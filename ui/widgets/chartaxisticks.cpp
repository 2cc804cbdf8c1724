// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/chartaxisticks.h"

#include <algorithm>
#include <cmath>

namespace slew::ui {

namespace {

constexpr double kMargin = 0.08;         // share of the span left free above and below the data
constexpr double kPixelsPerTick = 24.0;  // a label's height and some air between two
constexpr int kMostTicks = 6;

} // namespace

AxisTicks wholeNumberTicks(double lo, double hi, int maxTicks)
{
    maxTicks = std::max(2, maxTicks);
    if (!(lo <= hi) || !std::isfinite(lo) || !std::isfinite(hi)) {
        lo = 0.0;
        hi = 1.0;
    }
    if (hi - lo < 1e-9) {
        // Flat: one whole step either side of the value.
        lo -= 1.0;
        hi += 1.0;
    } else {
        const double margin = (hi - lo) * kMargin;
        lo -= margin;
        hi += margin;
    }
    AxisTicks t;
    t.min = lo;
    t.max = hi;
    for (double decade = 1.0;; decade *= 10.0) {
        for (double factor : {1.0, 2.0, 5.0}) {
            const double step = factor * decade;
            const double first = std::ceil(lo / step - 1e-9) * step;
            const double last = std::floor(hi / step + 1e-9) * step;
            const int count = int(std::lround((last - first) / step)) + 1;
            if (count <= maxTicks || decade > 1e12) {
                t.step = step;
                t.firstTick = first;
                t.count = count;
                if (count < 2) {
                    // Too few multiples inside: widen to the ones either side.
                    t.min = std::min(lo, std::floor(lo / step) * step);
                    t.max = std::max(hi, std::ceil(hi / step) * step);
                    t.firstTick = t.min;
                    t.count = int(std::lround((t.max - t.min) / step)) + 1;
                }
                return t;
            }
        }
    }
}

int ticksForHeight(double pixels)
{
    return std::clamp(int(pixels / kPixelsPerTick) + 1, 2, kMostTicks);
}

} // namespace slew::ui
