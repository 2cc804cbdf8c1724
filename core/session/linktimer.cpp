// SPDX-License-Identifier: GPL-3.0-or-later
#include "linktimer.h"

#include "transport/link.h"

namespace slew::session {

LinkTimer::LinkTimer(QObject *parent) : QObject(parent)
{
    connect(&m_wall, &QTimer::timeout, this, &LinkTimer::timeout);
}

void LinkTimer::setSingleShot(bool singleShot)
{
    m_singleShot = singleShot;
    m_wall.setSingleShot(singleShot);
}

void LinkTimer::setInterval(int ms)
{
    m_intervalMs = ms;
    m_wall.setInterval(ms);
}

void LinkTimer::start(int ms)
{
    setInterval(ms);
    start();
}

void LinkTimer::start()
{
    if (m_stepped) {
        m_deadline = linkNow() + m_intervalMs / 1000.0;
        return;
    }
    m_wall.start();
}

void LinkTimer::stop()
{
    m_wall.stop();
    m_deadline.reset();
}

bool LinkTimer::isActive() const
{
    return m_deadline.has_value() || m_wall.isActive();
}

void LinkTimer::followClockOf(transport::Link *link)
{
    const bool wasActive = isActive();
    stop();
    disconnect(m_steps);
    m_stepped = (link && link->clockIsStepped() && link->clockSeconds()) ? link : nullptr;
    if (m_stepped)
        m_steps = connect(m_stepped, &transport::Link::clockStepped, this, &LinkTimer::onClockStepped);
    if (wasActive)
        start();
}

double LinkTimer::linkNow() const
{
    return m_stepped ? m_stepped->clockSeconds().value_or(0.0) : 0.0;
}

void LinkTimer::onClockStepped()
{
    // Looked at from the event loop, after what the same step released
    // (a reply the device sent meanwhile) has been read: a reply that is
    // due at the deadline must win over the timeout.
    if (!m_deadline || m_checkQueued)
        return;
    m_checkQueued = true;
    QMetaObject::invokeMethod(this, &LinkTimer::fireIfDue, Qt::QueuedConnection);
}

void LinkTimer::fireIfDue()
{
    m_checkQueued = false;
    if (!m_deadline || !m_stepped || linkNow() < *m_deadline)
        return;
    if (m_singleShot) {
        m_deadline.reset();
    } else {
        // One timeout per step at most, as a late QTimer gives; the next
        // period counts from now so a big step does not queue a burst.
        m_deadline = linkNow() + m_intervalMs / 1000.0;
    }
    emit timeout();
}

} // namespace slew::session
