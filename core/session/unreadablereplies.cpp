// SPDX-License-Identifier: GPL-3.0-or-later
#include "unreadablereplies.h"

namespace slew::session {

bool UnreadableReplies::noteUnreadable(qint64 nowMs)
{
    if (nowMs < m_lastUnreadableMs) // time went back: the counts mean nothing now
        m_seconds = {};
    m_lastUnreadableMs = nowMs;
    const qint64 second = nowMs / 1000;
    Second &slot = m_seconds[size_t(second % kWindowSeconds)];
    if (slot.second != second)
        slot = Second{second, 0};
    if (slot.count < kRaiseAt * 1000) // enough to decide; no overflow in a flood
        ++slot.count;
    if (m_raised || inWindow(nowMs) < kRaiseAt)
        return false;
    m_raised = true;
    return true;
}

bool UnreadableReplies::noteReadable(qint64 nowMs)
{
    if (!m_raised)
        return false;
    const bool quietForAWindow = nowMs < m_lastUnreadableMs || nowMs - m_lastUnreadableMs >= kWindowSeconds * 1000;
    if (!quietForAWindow)
        return false;
    m_raised = false;
    m_seconds = {};
    return true;
}

int UnreadableReplies::inWindow(qint64 nowMs) const
{
    const qint64 now = nowMs / 1000;
    int n = 0;
    for (const Second &s : m_seconds) {
        if (s.second >= 0 && s.second <= now && s.second > now - kWindowSeconds)
            n += s.count;
    }
    return n;
}

} // namespace slew::session
