#include "rotatormotion.h"

#include "jogpad.h"

#include <cmath>

namespace slew::ui {

using session::RotatorSession;

RotatorMotion::RotatorMotion(RotatorSession *session, const JogPad *jog, QObject *parent)
    : QObject(parent), m_session(session), m_jog(jog)
{
    connect(session, &RotatorSession::positionChanged, this, &RotatorMotion::onPosition);
    // A new link starts with no history: readings from before it say nothing.
    connect(session, &RotatorSession::stateChanged, this, [this] {
        m_last.reset();
        m_changed = false;
    });
}

void RotatorMotion::onPosition(double az, double el, bool stale)
{
    if (stale)
        return;
    const QPointF now(az, el);
    m_changed = m_last && (std::abs(now.x() - m_last->x()) > kStillDeg || std::abs(now.y() - m_last->y()) > kStillDeg);
    m_last = now;
}

bool RotatorMotion::isMoving() const
{
    if (!m_session->isConnected())
        return false; // nothing to stop: Stop would reach no controller
    if (!m_session->hasPosition() || m_session->positionStale())
        return true;
    if (m_session->status().anyMoving())
        return true;
    for (JogPad::Direction d : {JogPad::Left, JogPad::Right, JogPad::Up, JogPad::Down}) {
        if (m_jog->isHeld(d))
            return true;
    }
    if (const auto target = m_session->activeTarget()) {
        if (std::abs(target->azimuth - m_session->azimuth()) > kArrivedDeg
            || std::abs(target->elevation - m_session->elevation()) > kArrivedDeg)
            return true;
    }
    return m_changed;
}

} // namespace slew::ui
