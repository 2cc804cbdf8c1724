// SPDX-License-Identifier: GPL-3.0-or-later
#include "stationclock.h"

#include "sky/skyvector.h"
#include "sky/utctime.h"

#include <algorithm>
#include <cmath>

namespace slew::tracking {

StationClock::StationClock(std::optional<double> startJulian, double rate, QObject *parent)
    : QObject(parent), m_start(startJulian), m_rate(startJulian ? rate : 1.0)
{
    m_elapsed.start();
}

double StationClock::nowJulian() const
{
    if (m_heldAt)
        return *m_heldAt;
    if (!m_start)
        return sky::julianNow();
    // Nanoseconds: at 20 times, whole milliseconds would step the clock by 20 ms.
    return *m_start + m_rate * double(m_elapsed.nsecsElapsed()) / 1e9 / sky::kSecondsPerDay;
}

void StationClock::rehearse(double startJulian, double rate)
{
    const bool wasPaused = isPaused();
    m_heldAt.reset();
    m_start = startJulian;
    m_rate = std::clamp(rate, 1.0, kMaxRate);
    m_elapsed.restart();
    emit changed();
    if (wasPaused)
        emit pausedChanged(false);
}

void StationClock::setRate(double rate)
{
    rate = std::clamp(rate, 1.0, kMaxRate);
    if (!m_start || rate == m_rate)
        return;
    if (!isPaused()) {
        rehearse(nowJulian(), rate);
        return;
    }
    // Held: the instant stays; the new rate applies from the resume.
    m_rate = rate;
    emit changed();
}

void StationClock::followRealTime()
{
    if (!m_start)
        return;
    const bool wasPaused = isPaused();
    m_heldAt.reset();
    m_start.reset();
    m_rate = 1.0;
    emit changed();
    if (wasPaused)
        emit pausedChanged(false);
}

void StationClock::pause()
{
    if (isPaused())
        return;
    const double now = nowJulian();
    if (!m_start)
        m_start = now; // the rehearsal begins where real time was
    m_heldAt = now;
    emit pausedChanged(true);
}

bool StationClock::holdAt(double julian)
{
    if (!isPaused() || !std::isfinite(julian))
        return false;
    m_start = julian;
    m_heldAt = julian;
    m_elapsed.restart();
    emit changed(); // a jump: whoever planned by the clock plans again
    return true;
}

void StationClock::resume()
{
    if (!isPaused())
        return;
    m_start = *m_heldAt;
    m_heldAt.reset();
    m_elapsed.restart();
    emit pausedChanged(false);
}

bool StationClock::step(double seconds)
{
    if (!isPaused() || !std::isfinite(seconds) || seconds <= 0.0)
        return false;
    *m_heldAt += seconds / sky::kSecondsPerDay;
    emit stepped();
    return true;
}

} // namespace slew::tracking
