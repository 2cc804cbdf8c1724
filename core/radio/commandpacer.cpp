// SPDX-License-Identifier: GPL-3.0-or-later
#include "commandpacer.h"

#include <algorithm>

namespace slew::radio {

CommandPacer::CommandPacer(QObject *parent) : QObject(parent)
{
    m_quietTimer.setSingleShot(true);
    m_quietTimer.setTimerType(Qt::PreciseTimer); // the interval is a floor: never fire early
    connect(&m_quietTimer, &QTimer::timeout, this, &CommandPacer::pump);
}

void CommandPacer::submit(const PacedCommand &command)
{
    const auto same = std::find_if(m_waiting.begin(), m_waiting.end(),
                                   [&](const PacedCommand &c) { return c.kind == command.kind; });
    if (same != m_waiting.end()) {
        *same = command; // its place in line, the newest value
        ++m_replaced;
    } else {
        m_waiting.push_back(command);
    }
    pump();
}

void CommandPacer::submitFirst(const PacedCommand &command)
{
    const auto same = std::find_if(m_waiting.begin(), m_waiting.end(),
                                   [&](const PacedCommand &c) { return c.kind == command.kind; });
    if (same != m_waiting.end()) {
        m_waiting.erase(same);
        ++m_replaced;
    }
    m_waiting.insert(m_waiting.begin(), command);
    pump();
}

void CommandPacer::finished(const std::optional<PacedCommand> &next)
{
    if (!m_inFlight)
        return; // after clear(): an answer that no longer has a command
    m_inFlight.reset();
    m_followUp = next;
    m_sinceFinished.start();
    pump();
}

void CommandPacer::clear()
{
    m_inFlight.reset();
    m_followUp.reset();
    m_waiting.clear();
    m_quietTimer.stop();
    m_sinceFinished.invalidate(); // a new connection starts without a wait
}

void CommandPacer::dropWaiting()
{
    m_waiting.clear();
    if (!m_followUp)
        m_quietTimer.stop(); // nothing left to wait out the interval for
}

void CommandPacer::setMinimumIntervalMs(int ms)
{
    m_minimumIntervalMs = std::max(ms, 0);
    // A command waiting out the old interval goes by the new one.
    if (m_quietTimer.isActive()) {
        m_quietTimer.stop();
        pump();
    }
}

qint64 CommandPacer::quietLeftMs() const
{
    if (!m_sinceFinished.isValid())
        return 0;
    return std::max<qint64>(0, m_minimumIntervalMs - m_sinceFinished.elapsed());
}

void CommandPacer::pump()
{
    // A link that answers inside ready() (a synchronous one) calls
    // finished() from there; the loop below then goes on, rather than
    // recursing once per command.
    if (m_pumping)
        return;
    m_pumping = true;
    while (!m_inFlight && (m_followUp || !m_waiting.empty())) {
        if (const qint64 left = quietLeftMs(); left > 0) {
            m_quietTimer.start(int(left));
            break;
        }
        if (m_followUp) {
            m_inFlight = std::move(m_followUp);
            m_followUp.reset();
        } else {
            m_inFlight = m_waiting.front();
            m_waiting.erase(m_waiting.begin());
        }
        const PacedCommand sending = *m_inFlight; // ready() may finish it
        emit ready(sending);
    }
    m_pumping = false;
}

} // namespace slew::radio
