// SPDX-License-Identifier: GPL-3.0-or-later
#include "remotejog.h"

#include "session/rotatorsession.h"

namespace slew::station {

using session::Axis;
using session::RotatorSession;

RemoteJog::RemoteJog(RotatorSession *session, QObject *parent) : QObject(parent), m_session(session)
{
    m_lease.setSingleShot(true);
    // Precise: a lease of 300 ms must not run 20 ms long on a coarse timer.
    m_lease.setTimerType(Qt::PreciseTimer);
    connect(&m_lease, &QTimer::timeout, this, &RemoteJog::onExpired);
    // A stop from anywhere (the window, a tracker, shutdown) or a lost link
    // ends the lease; there is nothing left to stop.
    connect(session, &RotatorSession::stopSent, this, &RemoteJog::release);
    connect(session, &RotatorSession::stateChanged, this, [this](RotatorSession::State s) {
        if (s != RotatorSession::State::Connected)
            release();
    });
}

session::CommandResult RemoteJog::turn(Axis axis, double speed, double &current)
{
    if (speed == current)
        return {};
    session::CommandResult result = speed == 0.0
                                        ? m_session->stop(tr("a remote jog at 0°/s"),
                                                          axis == Axis::Azimuth ? session::Axes::Azimuth
                                                                                : session::Axes::Elevation)
                                        : m_session->moveAxis(axis, speed);
    if (result)
        current = speed;
    return result;
}

session::CommandResult RemoteJog::jog(double azSpeed, double elSpeed, int leaseMs)
{
    // A stop of one axis here must not end the lease of the other: the
    // session's stopSent() ends it for stops from elsewhere.
    m_turning = true;
    session::CommandResult result = turn(Axis::Azimuth, azSpeed, m_azSpeed);
    if (result && !m_session->isAzimuthOnly())
        result = turn(Axis::Elevation, elSpeed, m_elSpeed);
    m_turning = false;
    if (!result || (m_azSpeed == 0.0 && m_elSpeed == 0.0)) {
        if (!result && (m_azSpeed != 0.0 || m_elSpeed != 0.0))
            m_session->stop(tr("a remote jog the rotator took only half of")); // half a jog is not what was asked
        m_azSpeed = m_elSpeed = 0;
        m_lease.stop();
        return result;
    }
    m_leaseMs = leaseMs;
    m_lease.start(leaseMs);
    return result;
}

void RemoteJog::release()
{
    if (m_turning)
        return;
    m_lease.stop();
    m_azSpeed = m_elSpeed = 0;
}

void RemoteJog::onExpired()
{
    const double az = m_azSpeed, el = m_elSpeed;
    m_azSpeed = m_elSpeed = 0;
    m_session->stop(tr("a remote jog's lease of %1 ms ran out").arg(m_leaseMs));
    emit expired(m_leaseMs, az, el);
}

} // namespace slew::station
