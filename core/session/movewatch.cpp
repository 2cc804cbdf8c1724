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
    // Where it stood when the move went out: a move that happens wholly
    // between two polls (a fast controller, a slow poll) is still motion.
    m_start.reset();
    if (m_session->hasPosition())
        m_start = QPointF(m_session->azimuth(), m_session->elevation());
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
    const protocol::FirmwareTraits &firmware = m_session->firmwareTraits();
    const bool movedFromStart = m_start && (bearingDifference(az, m_start->x()) > kRestDegrees
                                            || std::abs(el - m_start->y()) > kRestDegrees);
    m_sawMotion = m_sawMotion || (m_last && !steady) || movedFromStart || status.anyMoving();
    m_last = QPointF(az, el);
    // Rest is judged from motion: the position has stopped changing. A
    // status word saying idle shortens that to one steady pair, only where
    // the firmware sets its moving bit while it moves (not SatNOGS's, which
    // answers GS4 for a whole move; its steppers pause while it answers, so
    // two equal readings happen mid-move).
    const bool statusSaysIdle = firmware.statusShowsMotion && status.valid && status.idle();
    const bool atRest = m_steadyPolls >= kRestPolls || (statusSaysIdle && m_steadyPolls >= 1);
    if (!atRest)
        return;
    if (m_target ? arrived(*m_last) : m_sawMotion)
        finish(Outcome::Arrived);
    else if (m_sawMotion)
        finish(Outcome::StoppedShort);
}

bool MoveWatch::arrived(QPointF at) const
{
    // Within the controller's own tolerance is where it stops by design
    // (K3NG's 3° in azimuth, or what the profile says it was built with):
    // arrived, not short.
    return bearingDifference(at.x(), m_target->x()) <= std::max(kArrivedDegrees, m_session->azStopToleranceDeg())
           && std::abs(at.y() - m_target->y()) <= std::max(kArrivedDegrees, m_session->elStopToleranceDeg());
}

void MoveWatch::finish(Outcome outcome)
{
    m_watching = false;
    const QPointF at = m_last.value_or(QPointF(m_session->azimuth(), m_session->elevation()));
    emit ended(outcome, at, offTarget(at));
}

} // namespace slew::session
