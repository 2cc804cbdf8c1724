// SPDX-License-Identifier: GPL-3.0-or-later
#include "stationclock.h"

#include "sky/skyvector.h"
#include "sky/utctime.h"

#include <algorithm>

namespace slew::tracking {

StationClock::StationClock(std::optional<double> startJulian, double rate, QObject *parent)
    : QObject(parent), m_start(startJulian), m_rate(startJulian ? rate : 1.0)
{
    m_elapsed.start();
}

double StationClock::nowJulian() const
{
    if (!m_start)
        return sky::julianNow();
    // Nanoseconds: at 20 times, whole milliseconds would step the clock by 20 ms.
    return *m_start + m_rate * double(m_elapsed.nsecsElapsed()) / 1e9 / sky::kSecondsPerDay;
}

void StationClock::rehearse(double startJulian, double rate)
{
    m_start = startJulian;
    m_rate = std::clamp(rate, 1.0, kMaxRate);
    m_elapsed.restart();
    emit changed();
}

void StationClock::setRate(double rate)
{
    rate = std::clamp(rate, 1.0, kMaxRate);
    if (!m_start || rate == m_rate)
        return;
    rehearse(nowJulian(), rate);
}

void StationClock::followRealTime()
{
    if (!m_start)
        return;
    m_start.reset();
    m_rate = 1.0;
    emit changed();
}

} // namespace slew::tracking
