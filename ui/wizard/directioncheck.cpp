// SPDX-License-Identifier: GPL-3.0-or-later
#include "wizard/directioncheck.h"

#include "session/rotatorsession.h"

#include <cmath>

namespace slew::ui {

using session::Axis;
using session::RotatorSession;

namespace {
// This far the wrong way is no settling wobble or play in the gears: the
// axis is being driven away from its target.
constexpr double kWrongWayDeg = 1.0;
// This share of the jog covered towards the target: the reading agrees.
constexpr double kRightWayShare = 0.5;
} // namespace

DirectionCheck::DirectionCheck(RotatorSession *session, Axis axis, QObject *parent)
    : QObject(parent), m_session(session), m_axis(axis)
{
}

double DirectionCheck::reading() const
{
    return m_axis == Axis::Azimuth ? m_session->azimuth() : m_session->elevation();
}

QString DirectionCheck::way() const
{
    if (m_axis == Axis::Azimuth)
        return m_upward ? tr("clockwise") : tr("counter-clockwise");
    return m_upward ? tr("up") : tr("down");
}

bool DirectionCheck::start(double degrees)
{
    m_error.clear();
    if (!m_session->hasPosition()) {
        m_error = tr("No position from the rotator yet.");
        return false;
    }
    const bool azimuth = m_axis == Axis::Azimuth;
    const model::RotatorLimits &limits = m_session->moveGate().limits();
    const double from = reading();
    // Up (clockwise) unless that would run into the stop; then down.
    const bool upward = from + degrees <= (azimuth ? limits.azMax : limits.elMax);
    const double target = upward ? from + degrees : from - degrees;
    // The azimuth as the mechanical angle it is, not as a bearing the gate
    // might reach the other way round the overlap.
    const session::CommandResult sent = azimuth
        ? m_session->gotoAxis(Axis::Azimuth, target, RotatorSession::AzimuthIs::Position)
        : m_session->gotoAxis(Axis::Elevation, target);
    if (!sent) {
        m_error = tr("The jog was refused: %1").arg(sent.refusal);
        return false;
    }
    m_upward = upward;
    m_from = from;
    m_target = target;
    QObject::disconnect(m_watch);
    m_watch = connect(m_session, &RotatorSession::positionChanged, this, &DirectionCheck::onPosition);
    conclude(Verdict::Watching);
    return true;
}

void DirectionCheck::stop()
{
    if (m_verdict == Verdict::Watching)
        conclude(Verdict::Stopped);
}

void DirectionCheck::onPosition()
{
    const double sign = m_upward ? 1.0 : -1.0;
    const double gone = (reading() - m_from) * sign; // towards the target: positive
    if (gone <= -kWrongWayDeg) {
        m_wrongReading = reading();
        // The loop is driving the axis away from its target, and would go on
        // into the end stop: stopped before anything else is said.
        m_session->stop(tr("the direction check saw the axis go the wrong way"));
        conclude(Verdict::WrongWay);
    } else if (gone >= kRightWayShare * std::fabs(m_target - m_from)) {
        conclude(Verdict::RightWay);
    }
}

void DirectionCheck::conclude(Verdict verdict)
{
    if (verdict != Verdict::Watching)
        QObject::disconnect(m_watch);
    m_verdict = verdict;
    emit verdictChanged();
}

QString DirectionCheck::describe() const
{
    const QString axis = m_axis == Axis::Azimuth ? tr("Azimuth") : tr("Elevation");
    switch (m_verdict) {
    case Verdict::NotRun:
        return {};
    case Verdict::Watching:
        return tr("Watch the antenna: %1 should move %2, %3° from %4° to %5°.")
            .arg(axis.toLower(), way())
            .arg(std::fabs(m_target - m_from), 0, 'f', 0)
            .arg(m_from, 0, 'f', 1)
            .arg(m_target, 0, 'f', 1);
    case Verdict::RightWay:
        return tr("%1 reads %2 from %3° towards %4°, as sent. Tick below once you saw the antenna move %2 too.")
            .arg(axis, way())
            .arg(m_from, 0, 'f', 1)
            .arg(m_target, 0, 'f', 1);
    case Verdict::WrongWay:
        return tr("%1 ran the wrong way: sent %2 from %3° to %4°, it read %5°, so the rotator was stopped. The "
                  "motor (or its position sensor) is wired the wrong way round: swap it before going on.")
            .arg(axis, way())
            .arg(m_from, 0, 'f', 1)
            .arg(m_target, 0, 'f', 1)
            .arg(m_wrongReading, 0, 'f', 1);
    case Verdict::Stopped:
        return tr("Stopped before the reading showed which way %1 turns. Jog again to check.").arg(axis.toLower());
    }
    return {};
}

} // namespace slew::ui
