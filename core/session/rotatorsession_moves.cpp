// SPDX-License-Identifier: GPL-3.0-or-later
// RotatorSession's moves: go-to, relative moves, jogs, stop, park and
// home. Every move is checked against the limits before a byte is sent,
// and written as the codec (protocol/codec.h) says. Also here: the session
// moves only once it has read where the antenna is.
// The other files of the session: rotatorsession.cpp (the link),
// rotatorsession_replies.cpp (what comes back), rotatorsession_queries.cpp
// (the queue, the probe, polling), rotatorsession_registers.cpp (config and
// park registers), rotatorsession_rawlines.cpp (the operator's raw lines).

#include "rotatorsession.h"

#include "transport/link.h"

#include <algorithm>
#include <cmath>

namespace slew::session {

using protocol::Message;
using protocol::Op;

namespace {

// How long after SA / SE the zero-speed hold follows. A self-locking (worm)
// drive is at rest well within it, so the hold changes nothing there; a
// free-running drive has coasted this long and is then braked by the speed
// loop. Sent at once, the hold would replace the worm's instant stop with
// the driver's gentler braking ramp.
constexpr int kStopHoldDelayMs = 250;

} // namespace

// --- Commands ---------------------------------------------------------------
//
// Every move asks m_gate (model/movegate.h) before anything is written, and
// sends what the gate decided: the azimuth it chose, not the one asked for.

std::optional<double> RotatorSession::knownAzimuth() const
{
    return hasPosition() ? std::optional<double>(m_az) : std::nullopt;
}

namespace {

model::RotatorLimits shifted(model::RotatorLimits l, double az, double el)
{
    l.azMin += az;
    l.azMax += az;
    l.elMin += el;
    l.elMax += el;
    return l;
}

} // namespace

void RotatorSession::updateGateLimits()
{
    // An azimuth-only controller (Micro-2g) has no elevation to go to: the
    // gate allows elevation 0 alone, so every path refuses any other there.
    model::RotatorLimits limits = m_profile.limits;
    if (isAzimuthOnly())
        limits.elMin = limits.elMax = 0.0;
    m_gate.setProfileLimits(shifted(limits, azimuthOffset(), elevationOffset()));
    m_gate.setReportedLimits(m_linkLimits ? std::optional(shifted(*m_linkLimits, azimuthOffset(), elevationOffset()))
                                          : std::nullopt);
}

double RotatorSession::withinOffsetReach(double el) const
{
    const double offset = elevationOffset();
    if (offset == 0.0 || !std::isfinite(el))
        return el;
    const model::RotatorLimits reach = m_gate.limits();
    const model::RotatorLimits travel = shifted(reach, 0.0, -offset); // the controller's own
    if (el < travel.elMin || el > travel.elMax)
        return el; // beyond the travel itself: the gate says why
    return std::clamp(el, reach.elMin, reach.elMax);
}

model::MoveCheck RotatorSession::previewPointing(double az, double el) const
{
    return m_gate.pointing(az, withinOffsetReach(el), knownAzimuth());
}

model::MoveCheck RotatorSession::previewParkRegister(int reg, double value) const
{
    return reg == 7 ? m_gate.azimuthPosition(value + azimuthOffset())
                    : m_gate.elevation(value + elevationOffset());
}

CommandResult RotatorSession::gotoPosition(double az, double el)
{
    if (auto linked = requireLink(); !linked)
        return linked;
    if (auto seen = requirePositionRead(); !seen)
        return seen;
    el = withinOffsetReach(el);
    const model::MoveCheck check = m_gate.pointing(az, el, knownAzimuth());
    if (!check.allowed())
        return refuseMove(check.refusal);
    return sendSetPosition(check.azimuth, el);
}

CommandResult RotatorSession::gotoAxis(Axis axis, double degrees, AzimuthIs meaning)
{
    if (auto linked = requireLink(); !linked)
        return linked;
    if (auto seen = requirePositionRead(); !seen)
        return seen;
    const bool az = axis == Axis::Azimuth;
    if (!az)
        degrees = withinOffsetReach(degrees);
    const model::MoveCheck check = !az ? m_gate.elevation(degrees)
        : meaning == AzimuthIs::Bearing ? m_gate.azimuthBearing(degrees, knownAzimuth())
                                        : m_gate.azimuthPosition(degrees);
    if (!check.allowed())
        return refuseMove(check.refusal);
    const double target = az ? check.azimuth : check.elevation;
    // Easycomm I, GS-232 and rotctld can only command both axes together:
    // the other axis goes on to where it was last sent, or stays where it
    // was last seen, and the pair passes the gate as the mechanical
    // positions that are sent.
    if (m_codec->setsBothAxes()) {
        std::optional<double> other;
        if (m_activeTarget)
            other = az ? m_activeTarget->elevation : m_activeTarget->azimuth;
        else if (hasPosition())
            other = az ? m_el : m_az;
        if (!other)
            return refuse(tr("%1 moves both axes at once, and the other axis' position is not known yet")
                              .arg(m_codec->name()));
        const double a = az ? target : *other;
        const double e = az ? *other : target;
        if (const model::MoveCheck both = m_gate.mechanical(a, e); !both.allowed())
            return refuseMove(both.refusal);
        return sendSetPosition(a, e);
    }
    if (const QString held = az ? motionHold(target, std::nullopt) : motionHold(std::nullopt, target); !held.isEmpty())
        return refuseMove(held);
    const double wire = target - (az ? azimuthOffset() : elevationOffset());
    const protocol::Encoded set = m_codec->setAxis(az, wire);
    if (!set.ok())
        return refuse(set.refusal);
    rememberSent(Message::number(az ? Op::Azimuth : Op::Elevation, std::round(wire * 100) / 100));
    m_jogSpeed[az ? 0 : 1] = 0.0;
    writeMove(set.bytes);
    // The other axis keeps going where it was going, if that is known.
    if (m_activeTarget)
        (az ? m_activeTarget->azimuth : m_activeTarget->elevation) = target;
    (az ? m_targetAz : m_targetEl) = target;
    guardAxis(axis, target); // the other axis goes on as it was watched
    emit targetChanged(m_targetAz, m_targetEl);
    return {};
}

CommandResult RotatorSession::moveBy(double azimuthOffset, double elevationOffset)
{
    if (auto linked = requireLink(); !linked)
        return linked;
    if (!std::isfinite(azimuthOffset) || !std::isfinite(elevationOffset))
        return refuse(tr("an offset is not a number"));
    if (!hasPosition())
        return refuse(tr("a relative move needs the present position, which is not known yet"));
    // The offsets are added to the position the session last read, and the
    // sum is checked and sent as such: the controller is told
    // where to go, not how far, so it cannot end up anywhere the gate did
    // not see even if it has moved since the last poll.
    const double a = m_az + azimuthOffset;
    const double e = m_el + elevationOffset;
    const model::MoveCheck check = m_gate.mechanical(a, e);
    if (!check.allowed())
        return refuseMove(check.refusal);
    return sendSetPosition(a, e);
}

CommandResult RotatorSession::gotoUnwrapped(double azimuth, double elevation)
{
    if (auto linked = requireLink(); !linked)
        return linked;
    if (auto seen = requirePositionRead(); !seen)
        return seen;
    if (!std::isfinite(azimuth) || !std::isfinite(elevation))
        return refuse(tr("a position is not a number"));
    elevation = withinOffsetReach(elevation);
    const model::MoveCheck check = m_gate.mechanical(azimuth, elevation);
    if (!check.allowed())
        return refuseMove(check.refusal);
    return sendSetPosition(azimuth, elevation);
}

double RotatorSession::setResolutionDeg() const
{
    return m_codec->setResolutionDeg();
}

CommandResult RotatorSession::sendSetPosition(double az, double el)
{
    if (const QString held = motionHold(az, isAzimuthOnly() ? std::nullopt : std::optional<double>(el)); !held.isEmpty())
        return refuseMove(held);
    const double wireAz = az - azimuthOffset();
    const double wireEl = el - elevationOffset();
    const protocol::Encoded set = m_codec->setPosition(wireAz, wireEl);
    if (!set.ok())
        return refuse(set.refusal);
    rememberSent(Message::number(Op::Azimuth, std::round(wireAz * 100) / 100));
    rememberSent(Message::number(Op::Elevation, std::round(wireEl * 100) / 100));
    m_jogSpeed = {0.0, 0.0};
    writeMove(set.bytes);
    m_activeTarget = PointingTarget{az, el};
    m_targetAz = az;
    m_targetEl = el;
    guardMove(az, el);
    emit targetChanged(az, el);
    return {};
}

CommandResult RotatorSession::moveAxis(Axis axis, double degreesPerSecond)
{
    if (auto linked = requireLink(); !linked)
        return linked;
    if (auto seen = requirePositionRead(); !seen)
        return seen;
    if (!std::isfinite(degreesPerSecond))
        return refuse(tr("speed is not a number"));
    if (degreesPerSecond == 0.0)
        return stop(tr("a jog at 0°/s"), axis == Axis::Azimuth ? Axes::Azimuth : Axes::Elevation);
    const bool az = axis == Axis::Azimuth;
    const bool positive = degreesPerSecond > 0;
    const std::optional<double> at = hasPosition() ? std::optional<double>(az ? m_az : m_el) : std::nullopt;
    if (const model::MoveCheck check = m_gate.drive(az, positive, at); !check.allowed())
        return refuseMove(check.refusal);
    if (const QString held = axisHeld(az ? Axis::Azimuth : Axis::Elevation); !held.isEmpty())
        return refuseMove(held); // a jog drives it, wherever it goes
    if (!m_codec->jogsItself())
        return jogBySetPosition(axis, degreesPerSecond);
    std::array<double, 2> speeds = m_jogSpeed;
    speeds[az ? 0 : 1] = degreesPerSecond;
    const protocol::Encoded jog = m_codec->jog(speeds, az);
    if (!jog.ok())
        return refuse(jog.refusal);
    if (jog.echo)
        rememberSent(*jog.echo);
    m_jogSpeed = speeds;
    writeMove(jog.bytes);
    m_activeTarget.reset(); // the axis runs at a speed now, towards no target
    guardJog();
    return {};
}

JogLegs::Where RotatorSession::jogWhere() const
{
    JogLegs::Where here{m_az, m_el, m_gate.limits(), std::nullopt};
    if (isAzimuthOnly())
        here.fixedElevation = elevationOffset();
    return here;
}

CommandResult RotatorSession::jogBySetPosition(Axis axis, double degreesPerSecond)
{
    if (!hasPosition())
        return refuse(tr("a jog needs the present position, which is not known yet"));
    const bool az = axis == Axis::Azimuth;
    std::array<double, 2> jogging = m_jogSpeed;
    jogging[az ? 0 : 1] = degreesPerSecond;
    const std::optional<std::array<double, 2>> leg = JogLegs::leg(jogging, az ? 0 : 1, jogWhere());
    if (!leg)
        return refuseMove(tr("the %1 is at the end of its travel that way").arg(az ? tr("azimuth") : tr("elevation")));
    const model::MoveCheck check = m_gate.mechanical((*leg)[0], (*leg)[1]);
    if (!check.allowed())
        return refuseMove(check.refusal);
    if (const CommandResult sent = sendSetPosition((*leg)[0], (*leg)[1]); !sent)
        return sent;
    m_jogSpeed = jogging;     // sendSetPosition ended every jog; these go on
    m_jogLegs.started(*leg);
    m_activeTarget.reset();   // running to an end, towards no target of the operator's
    guardJog();               // watched as a jog: the leg's end is no target
    return {};
}

CommandResult RotatorSession::stop(const QString &cause, Axes axes)
{
    // Stop goes straight to the wire, ahead of any waiting query, in every
    // state where there is a link to send it on. It is never gated.
    if (!m_link || !m_link->isOpen())
        return refuse(tr("not connected to a rotator: nothing to stop"));
    const bool az = int(axes) & int(Axes::Azimuth);
    const bool el = int(axes) & int(Axes::Elevation);
    if (az)
        m_jogSpeed[0] = 0.0;
    if (el)
        m_jogSpeed[1] = 0.0;
    const QByteArray line = m_codec->stop(az, el);
    if (line.isEmpty())
        return refuse(tr("%1 has no stop command").arg(m_codec->name()));
    m_activeTarget.reset();
    for (size_t i = 0; i < 2; ++i) {
        if (m_codec->stopHaltsEveryAxis() || (i == 0 ? az : el))
            m_guards[i].release(); // a jog the stop does not end is watched again as it is sent again
    }
    write(line);
    m_refusals.noteCommand(line, nowMs());
    wakePolling(); // to see it come to rest
    emit stopSent(cause);
    emit targetCleared();
    // A stop that halts every axis: one still held on the jog pad runs on.
    if (m_codec->stopHaltsEveryAxis()) {
        for (Axis other : {Axis::Azimuth, Axis::Elevation}) {
            if (const double speed = m_jogSpeed[other == Axis::Azimuth ? 0 : 1]; speed != 0.0) {
                m_jogSpeed[other == Axis::Azimuth ? 0 : 1] = 0.0;
                moveAxis(other, speed);
            }
        }
    }
    // SA / SE only let go of the drive. Where the dialect has speed commands,
    // a zero speed follows to brake a drive that would coast (spur gear,
    // direct drive) and hold it there.
    if (!m_codec->stopHold(az, el).isEmpty()) {
        m_holdAzimuth = az || (m_stopHoldTimer.isActive() && m_holdAzimuth);
        m_holdElevation = el || (m_stopHoldTimer.isActive() && m_holdElevation);
        m_stopHoldTimer.start(kStopHoldDelayMs);
    }
    return {};
}

void RotatorSession::sendStopHold()
{
    write(m_codec->stopHold(m_holdAzimuth, m_holdElevation));
    m_holdAzimuth = m_holdElevation = false;
    emit stopHoldSent();
}

void RotatorSession::writeMove(const QByteArray &line)
{
    m_stopHoldTimer.stop();
    m_holdAzimuth = m_holdElevation = false;
    write(line);
    m_refusals.noteCommand(line, nowMs());
    wakePolling(); // the move is watched at the full rate from its start
    emit moveSent();
}

CommandResult RotatorSession::park()
{
    if (auto linked = requireLink(); !linked)
        return linked;
    if (auto seen = requirePositionRead(); !seen)
        return seen;
    if (!m_codec->supports(Op::Park) || !firmwareTraits().parkCommand) {
        const CommandResult sent = gotoPosition(parkAzimuth(), parkElevation());
        m_activeTarget.reset(); // parking is the operator's move, not a tracker target
        return sent;
    }
    // The controller parks where its own registers say: as read once they
    // are in, else the profile's position, which is what the wizard or the
    // Configuration tab wrote there (CW7/CW8 pass the gate). Either is
    // checked again against the limits in force now.
    const model::MoveCheck check = m_gate.mechanical(parkAzimuth(), parkElevation());
    if (!check.allowed())
        return refuseMove(tr("the park position: %1").arg(check.refusal));
    if (const QString held = motionHold(parkAzimuth(), parkElevation()); !held.isEmpty())
        return refuseMove(held);
    m_jogSpeed = {0.0, 0.0};
    writeMove(m_codec->line({Message::query(Op::Park)}));
    guardControllersOwnMove(); // it parks the way it chooses (0° may be 360°)
    m_activeTarget.reset();
    // A park not read yet is no target to show: the controller knows where
    // it goes, the session does not.
    if (parkKnown()) {
        m_targetAz = parkAzimuth();
        m_targetEl = parkElevation();
        emit targetChanged(m_targetAz, m_targetEl);
    } else {
        emit targetCleared();
    }
    return {};
}

CommandResult RotatorSession::home()
{
    // Homing goes ahead with no position read: it is how a controller that
    // counts steps (SatNOGS) learns where it is, and it ends on its switches.
    if (auto linked = requireLink(); !linked)
        return linked;
    if (!m_codec->supports(Op::Reset))
        return refuse(tr("%1 has no RESET (homing) command").arg(m_codec->name()));
    // Homing drives both axes to their switches: not while one is held.
    for (const QString &held : m_motionFaults)
        if (!held.isEmpty())
            return refuseMove(tr("homing drives both axes, and one is held after the motion guard stopped it (%1): "
                                 "clear the fault once it is looked at").arg(held));
    // The controller's own run to its switches, which it ends itself: not
    // watched (its speed and path are its own).
    guardMove(std::nullopt, std::nullopt);
    // Homing runs each axis to its lower limit switch: the controller's own
    // move, bounded by the switches rather than by soft limits.
    m_jogSpeed = {0.0, 0.0};
    writeMove(m_codec->line({Message::query(Op::Reset)}));
    m_activeTarget.reset();
    // Homing ends at the lower limits: that is where the rotator is going
    // now, not the last go-to.
    m_targetAz = m_profile.limits.azMin + azimuthOffset();
    m_targetEl = m_profile.limits.elMin + elevationOffset();
    emit targetChanged(m_targetAz, m_targetEl);
    return {};
}

bool RotatorSession::awaitingPosition() const
{
    // A controller that can report its position and has not: its replies
    // are unreadable (often the wrong dialect), so nothing confirms where
    // a move would start, whether it runs, or when it ends. Easycomm I
    // cannot be asked at all, and is driven as it always was.
    return !m_positionReadOnLink && !m_codec->queryPosition().isEmpty();
}

QString RotatorSession::positionNotRead() const
{
    if (!awaitingPosition())
        return {};
    return m_caps.probed && !m_caps.positionFeedback
        ? tr("no position read from the controller: check the dialect (%1)").arg(m_codec->name())
        : tr("no position read from the controller yet");
}

CommandResult RotatorSession::requirePositionRead(Report report)
{
    if (!awaitingPosition())
        return {};
    const QString why = positionNotRead();
    if (report == Report::Quietly)
        return CommandResult{why};
    return refuseMove(why);
}

} // namespace slew::session
