// SPDX-License-Identifier: GPL-3.0-or-later
#include "lineturnaround.h"

#include <algorithm>

namespace slew::session {

LineTurnaround::LineTurnaround(QObject *parent) : QObject(parent)
{
    m_timer.setSingleShot(true);
    connect(&m_timer, &LinkTimer::timeout, this, &LineTurnaround::releaseDue);
}

bool LineTurnaround::hold(const QByteArray &bytes, bool request, qint64 nowMs)
{
    if (m_turnaroundMs <= 0)
        return false;
    const bool lineFree = !m_awaitingReply && nowMs >= m_lastReceivedMs + m_turnaroundMs;
    if (m_held.empty() && lineFree) {
        m_awaitingReply = request;
        return false;
    }
    m_held.push_back({bytes, request});
    if (!m_timer.isActive())
        scheduleRelease(nowMs);
    return true;
}

void LineTurnaround::replyEnded(qint64 nowMs)
{
    if (!m_awaitingReply)
        return;
    m_awaitingReply = false;
    if (!m_held.empty())
        scheduleRelease(nowMs);
}

void LineTurnaround::scheduleRelease(qint64 nowMs)
{
    if (m_awaitingReply)
        m_timer.start(kLongestHoldMs); // the answer may never come
    else
        m_timer.start(int(std::max<qint64>(0, m_lastReceivedMs + m_turnaroundMs - nowMs)));
}

void LineTurnaround::releaseDue()
{
    // The pause is over, or no answer came within the longest hold: the
    // lines go, up to and with the next request, which waits for its own.
    m_awaitingReply = false;
    QByteArray bytes;
    while (!m_held.empty() && !m_awaitingReply) {
        bytes += m_held.front().bytes;
        m_awaitingReply = m_held.front().request;
        m_held.pop_front();
    }
    if (!m_held.empty())
        m_timer.start(kLongestHoldMs);
    if (!bytes.isEmpty())
        emit released(bytes);
    if (m_held.empty())
        emit drained();
}

void LineTurnaround::clear()
{
    m_timer.stop();
    const bool held = !m_held.empty();
    m_held.clear();
    m_awaitingReply = false;
    m_lastReceivedMs = -1'000'000;
    if (held)
        emit drained();
}

} // namespace slew::session
