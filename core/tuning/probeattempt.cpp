// SPDX-License-Identifier: GPL-3.0-or-later
#include "probeattempt.h"

#include "model/rotatorprofile.h"
#include "session/rotatorsession.h"

namespace slew::tuning {

ProbeAttempt::ProbeAttempt(QObject *owner, int limitMs, std::function<void()> timedOut) : m_owner(owner)
{
    m_timer.setSingleShot(true);
    m_timer.setInterval(limitMs);
    QObject::connect(&m_timer, &QTimer::timeout, owner, std::move(timedOut));
}

ProbeAttempt::~ProbeAttempt()
{
    end();
}

session::RotatorSession *ProbeAttempt::begin(protocol::Dialect dialect)
{
    end();
    m_session = std::make_unique<session::RotatorSession>();
    model::RotatorProfile profile;
    profile.dialect = dialect;
    m_session->setProfile(profile);
    return m_session.get();
}

void ProbeAttempt::go(const QString &uri)
{
    if (!m_session)
        return;
    m_timer.start();
    m_session->connectTo(uri);
}

void ProbeAttempt::end()
{
    m_timer.stop();
    if (!m_session)
        return;
    m_session->disconnect(m_owner);
    m_session->disconnectFromRotator();
    m_session.release()->deleteLater();
}

} // namespace slew::tuning
