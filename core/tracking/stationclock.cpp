// SPDX-License-Identifier: GPL-3.0-or-later
#include "stationclock.h"

#include "sky/skyvector.h"
#include "sky/utctime.h"

namespace slew::tracking {

StationClock::StationClock(std::optional<double> startJulian, double rate) : m_start(startJulian), m_rate(rate)
{
    if (!m_start) {
        m_start.reset();
        m_rate = 1.0;
    }
    m_elapsed.start();
}

double StationClock::nowJulian() const
{
    if (!m_start)
        return sky::julianNow();
    return *m_start + m_rate * m_elapsed.elapsed() / 1000.0 / sky::kSecondsPerDay;
}

} // namespace slew::tracking
