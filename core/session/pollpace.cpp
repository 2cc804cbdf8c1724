// SPDX-License-Identifier: GPL-3.0-or-later
#include "pollpace.h"

#include <algorithm>

namespace slew::session {

void PollPace::setIntervals(int fullMs, int restMs)
{
    m_fullMs = std::max(1, fullMs);
    m_restMs = std::max(m_fullMs, restMs);
}

void PollPace::wake(qint64 nowMs)
{
    m_lastWakeMs = nowMs;
}

void PollPace::notePosition(double az, double el, qint64 nowMs)
{
    const bool moved = std::isnan(m_stillAz) || std::abs(az - m_stillAz) > kMovedDegrees
                       || std::abs(el - m_stillEl) > kMovedDegrees;
    if (!moved)
        return;
    // The first position after a restart is where it stands, not motion:
    // the restart has woken the pace already.
    if (!std::isnan(m_stillAz))
        wake(nowMs);
    m_stillAz = az;
    m_stillEl = el;
}

void PollPace::restart(qint64 nowMs)
{
    m_stillAz = m_stillEl = NAN;
    wake(nowMs);
}

} // namespace slew::session
