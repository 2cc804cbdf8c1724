// SPDX-License-Identifier: GPL-3.0-or-later
#include "refusalowner.h"

namespace slew::session {

void RefusalOwner::noteCommand(const QByteArray &line, qint64 nowMs)
{
    m_commandAt = ++m_sequence;
    m_commandMs = nowMs;
    m_command = line;
}

void RefusalOwner::noteRequestWritten()
{
    m_requestAt = ++m_sequence;
}

void RefusalOwner::noteRequestAnswered()
{
    if (m_commandAt != 0 && m_requestAt > m_commandAt)
        m_commandAt = 0; // read before the request, and not refused
}

void RefusalOwner::reset()
{
    m_commandAt = 0;
    m_requestAt = 0;
    m_command.clear();
}

bool RefusalOwner::commandPending(qint64 nowMs) const
{
    return m_commandAt != 0 && nowMs - m_commandMs <= m_windowMs;
}

RefusalOwner::Answer RefusalOwner::take(bool requestOnWire, qint64 nowMs)
{
    if (commandPending(nowMs) && (!requestOnWire || m_commandAt < m_requestAt)) {
        m_commandAt = 0;
        return {Owner::Command, m_command};
    }
    if (requestOnWire)
        return {Owner::Request, {}};
    return {};
}

} // namespace slew::session
