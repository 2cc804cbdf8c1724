// SPDX-License-Identifier: GPL-3.0-or-later
#include "echofilter.h"

#include "protocol/operations.h"

#include <cmath>

namespace slew::session {

using protocol::Message;
using protocol::Op;

void EchoFilter::reset()
{
    m_controllerEchoes = false;
    m_sent = {}; // stamped with the last link's clock
    m_next = 0;
}

void EchoFilter::noteSent(const Message &m, qint64 nowMs)
{
    m_sent[size_t(m_next)] = Sent{m, nowMs};
    m_next = (m_next + 1) % int(m_sent.size());
}

bool EchoFilter::isEcho(const Message &m, qint64 nowMs)
{
    const bool echo = judge(m, nowMs);
    if (echo)
        ++m_ignored;
    return echo;
}

bool EchoFilter::judge(const Message &m, qint64 nowMs)
{
    // Unmistakable echoes: a command, or a query form, coming back. Seeing one
    // tells us this controller echoes what it hears.
    if (protocol::operationInfo(m.op).commandOnly
        || (m.op != Op::Alarm && m.op != Op::Invalid && !m.hasValue && m.text.isEmpty())) {
        m_controllerEchoes = true;
        return true;
    }
    if (m.op == Op::VelocityLeft || m.op == Op::VelocityRight || m.op == Op::VelocityUp
        || m.op == Op::VelocityDown)
        return true; // a controller reports speed in IP7/IP8, never as VL..VD
    // A set position coming back reads exactly like a position report, so it
    // is only taken for an echo from a controller known to echo, and only
    // when it repeats what was sent within the last second.
    if (!m_controllerEchoes || (m.op != Op::Azimuth && m.op != Op::Elevation))
        return false;
    for (const Sent &s : m_sent) {
        if (nowMs - s.atMs <= kWindowMs && s.message.op == m.op && s.message.hasValue
            && std::abs(s.message.value - m.value) < 1e-9)
            return true;
    }
    return false;
}

} // namespace slew::session
