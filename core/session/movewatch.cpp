// SPDX-License-Identifier: GPL-3.0-or-later
#include "movewatch.h"

#include "rotatorsession.h"

#include <algorithm>
#include <cmath>

namespace slew::session {

namespace {

// Two fresh positions this close are "not moving"; this many in a row, or
// one with the controller's status saying idle, is "at rest".
constexpr double kRestDegrees = 0.02;
constexpr int kRestPolls = 3;
// A target sent again this close is the same move (a tracker's repeat).
constexpr double kSameTargetDegrees = 0.01;

double bearingDifference(double a, double b)
{
    const double d = std::fmod(std::abs(a - b), 360.0);
    return std::min(d, 360.0 - d);
}

} // namespace

MoveWatch::MoveWatch(RotatorSession *session, QObject *parent) : QObject(parent), m_session(session)
{
    connect(session, &RotatorSession::positionChanged, this, &MoveWatch::onPosition);
    connect(session, &RotatorSession::stopSent, this, [this] {
        if (m_watching)
            finish(Outcome::Stopped);
    });
    connect(session, &RotatorSession::targetChanged, this, [this](double az, double el) {
        if (m_watching && (!m_target || bearingDifference(az, m_target->x()) > kSameTargetDegrees
                           || std::abs(el - m_target->y()) > kSameTargetDegrees))
            finish(Outcome::Replaced);
    });
    connect(session, &RotatorSession::controllerRefusedMove, this, [this](const QString &why) {
        if (!m_watching)
            return;
        m_refusal = why;
        finish(Outcome::Refused);
    });
    connect(session, &RotatorSession::stateChanged, this, [this](RotatorSession::State state) {
        if (m_watching && state != RotatorSession::State::Connected)
            finish(Outcome::LinkLost);
    });
}

void MoveWatch::watch(std::optional<QPointF> target)
{
    m_watching = true;
    m_target = target;
    m_last.reset();
    m_steadyPolls = 0;
    m_sawMotion = false;
    m_refusal.clear();
    // A move to where the rotator already rests ends at the next fresh position.
}

void MoveWatch::cancel()
{
    m_watching = false;
}

double MoveWatch::offTarget(QPointF at) const
{
    if (!m_target)
        return 0.0;
    return std::max(bearingDifference(at.x(), m_target->x()), std::abs(at.y() - m_target->y()));
}

void MoveWatch::onPosition(double az, double el, bool stale)
{
    if (!m_watching || stale)
        return;
    const bool steady = m_last && bearingDifference(az, m_last->x()) <= kRestDegrees
                        && std::abs(el - m_last->y()) <= kRestDegrees;
    m_steadyPolls = steady ? m_steadyPolls + 1 : 0;
    const StatusWord status = m_session->status();
    m_sawMotion = m_sawMotion || (m_last && !steady) || status.anyMoving();
    m_last = QPointF(az, el);
    const bool atRest = m_steadyPolls >= kRestPolls || (status.valid && status.idle() && m_steadyPolls >= 1);
    if (!atRest)
        return;
    if (m_target ? offTarget(*m_last) <= kArrivedDegrees : m_sawMotion)
        finish(Outcome::Arrived);
    else if (m_sawMotion)
        finish(Outcome::StoppedShort);
}

void MoveWatch::finish(Outcome outcome)
{
    m_watching = false;
    const QPointF at = m_last.value_or(QPointF(m_session->azimuth(), m_session->elevation()));
    emit ended(outcome, at, offTarget(at));
}

} // namespace slew::session
