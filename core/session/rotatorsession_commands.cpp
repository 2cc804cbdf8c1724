// SPDX-License-Identifier: GPL-3.0-or-later
// RotatorSession, part three: what the operator (or a tracker) asks of the
// rotator. Every move is checked against the limits before a byte is sent.

#include "rotatorsession.h"

#include "input/finitenumber.h"

#include "protocol/encoder.h"
#include "protocol/spidcodec.h"
#include "transport/link.h"

#include <algorithm>
#include <cmath>

namespace slew::session {

using protocol::Dialect;
using protocol::Message;
using protocol::Op;

namespace {

constexpr int kMaxRawLine = 200;

// How long after SA / SE the zero-speed hold follows. A self-locking (worm)
// drive is at rest well within it, so the hold changes nothing there; a
// free-running drive has coasted this long and is then braked by the speed
// loop. Sent at once, the hold would replace the worm's instant stop with
// the driver's gentler braking ramp.
constexpr int kStopHoldDelayMs = 250;

QString printable(const QByteArray &line)
{
    return QString::fromLatin1(line).trimmed();
}

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
    const Op op = az ? Op::Azimuth : Op::Elevation;
    const Dialect d = m_profile.dialect;
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
    if (protocol::setsBothAxesTogether(d)) {
        std::optional<double> other;
        if (m_activeTarget)
            other = az ? m_activeTarget->elevation : m_activeTarget->azimuth;
        else if (hasPosition())
            other = az ? m_el : m_az;
        if (!other)
            return refuse(tr("%1 moves both axes at once, and the other axis' position is not known yet")
                              .arg(protocol::dialectName(d)));
        const double a = az ? target : *other;
        const double e = az ? *other : target;
        if (const model::MoveCheck both = m_gate.mechanical(a, e); !both.allowed())
            return refuseMove(both.refusal);
        return sendSetPosition(a, e);
    }
    const double wire = target - (az ? azimuthOffset() : elevationOffset());
    const Message m = Message::number(op, wire);
    rememberSent(Message::number(op, std::round(wire * 100) / 100));
    m_jogSpeed[az ? 0 : 1] = 0.0;
    writeMove(protocol::encodeLine({m}, d));
    // The other axis keeps going where it was going, if that is known.
    if (m_activeTarget)
        (az ? m_activeTarget->azimuth : m_activeTarget->elevation) = target;
    (az ? m_targetAz : m_targetEl) = target;
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
    const Dialect d = m_profile.dialect;
    if (protocol::isSpid(d) && d != Dialect::Rot1Prog) {
        const int pulses = std::max(m_parser.spidAzimuthPulses(), m_parser.spidElevationPulses());
        return pulses > 0 ? 1.0 / pulses : 1.0;
    }
    return std::pow(10.0, -protocol::angleDecimals(d));
}

QByteArray RotatorSession::encodeSet(double wireAz, double wireEl, QString *why) const
{
    const Dialect d = m_profile.dialect;
    if (!protocol::isSpid(d)) {
        const QByteArray line = protocol::encodeSetPosition(wireAz, wireEl, d, m_rotor);
        if (line.isEmpty())
            *why = tr("%1 has no command to set a position").arg(protocol::dialectName(d));
        return line;
    }
    // A SPID set counts in the controller's pulses per degree, which only
    // its replies tell (Rot1Prog's whole degrees need none). Guessing would
    // send a Rot2Prog at resolution 2 to twice the angle.
    const int azPulses = m_parser.spidAzimuthPulses(), elPulses = m_parser.spidElevationPulses();
    if (d != Dialect::Rot1Prog && (azPulses == 0 || elPulses == 0)) {
        *why = tr("the controller's resolution is not known yet: it has not answered a status request");
        return {};
    }
    const protocol::spid::Encoded set = protocol::spid::encodeSet(wireAz, wireEl, d, azPulses, elPulses);
    if (!set.ok())
        *why = QString::fromLatin1(set.refusal);
    return set.bytes;
}

CommandResult RotatorSession::sendSetPosition(double az, double el)
{
    const double wireAz = az - azimuthOffset();
    const double wireEl = el - elevationOffset();
    QString why;
    const QByteArray line = encodeSet(wireAz, wireEl, &why);
    if (line.isEmpty())
        return refuse(why);
    rememberSent(Message::number(Op::Azimuth, std::round(wireAz * 100) / 100));
    rememberSent(Message::number(Op::Elevation, std::round(wireEl * 100) / 100));
    m_jogSpeed = {0.0, 0.0};
    writeMove(line);
    m_activeTarget = PointingTarget{az, el};
    m_targetAz = az;
    m_targetEl = el;
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
    const Dialect d = m_profile.dialect;
    const Op velocityOp = az ? (positive ? Op::VelocityRight : Op::VelocityLeft)
                             : (positive ? Op::VelocityUp : Op::VelocityDown);
    const Op moveOp = az ? (positive ? Op::MoveRight : Op::MoveLeft) : (positive ? Op::MoveUp : Op::MoveDown);
    QByteArray line;
    if (protocol::isSpid(d) && protocol::dialectSupports(d, moveOp)) {
        // The MD-01/02's move names every axis that is to run.
        m_jogSpeed[az ? 0 : 1] = degreesPerSecond;
        writeMove(spidMoveFrame());
        m_activeTarget.reset();
        return {};
    }
    if (protocol::isSpid(d))
        return jogBySetPosition(axis, degreesPerSecond);
    if (protocol::dialectSupports(d, velocityOp)) {
        const Message m = Message::number(velocityOp, std::round(std::abs(degreesPerSecond) * 1000.0));
        rememberSent(m);
        line = protocol::encodeLine({m}, d);
    } else if (protocol::dialectSupports(d, moveOp)) {
        line = protocol::encodeLine({Message::query(moveOp)}, d);
    } else {
        return refuse(tr("%1 has no command to move an axis").arg(protocol::dialectName(d)));
    }
    m_jogSpeed[az ? 0 : 1] = degreesPerSecond;
    writeMove(line);
    m_activeTarget.reset(); // the axis runs at a speed now, towards no target
    return {};
}

QByteArray RotatorSession::spidMoveFrame() const
{
    namespace Bit = protocol::spid::MoveBit;
    int directions = 0;
    if (m_jogSpeed[0] != 0.0)
        directions |= m_jogSpeed[0] > 0 ? Bit::Right : Bit::Left;
    if (m_jogSpeed[1] != 0.0)
        directions |= m_jogSpeed[1] > 0 ? Bit::Up : Bit::Down;
    return protocol::spid::encodeMove(directions, m_profile.dialect).bytes;
}

double RotatorSession::jogLegEnd(bool azimuth, double speed) const
{
    const model::RotatorLimits l = m_gate.limits();
    const double here = azimuth ? m_az : m_el;
    if (speed > 0)
        return std::min(azimuth ? l.azMax : l.elMax, here + kJogLegDeg);
    return std::max(azimuth ? l.azMin : l.elMin, here - kJogLegDeg);
}

CommandResult RotatorSession::jogBySetPosition(Axis axis, double degreesPerSecond)
{
    // Safe as a velocity jog is: every leg ends inside the gate, the
    // controller brakes there by itself, and Stop (the release, or any
    // other) ends it. The speed is the controller's own. A leg is less than
    // half a turn, so a controller that takes a set as a bearing and turns
    // the short way to it (360° is north, 0°) still turns the way the
    // operator pressed; the next leg follows before this one ends.
    if (!hasPosition())
        return refuse(tr("a jog needs the present position, which is not known yet"));
    const bool az = axis == Axis::Azimuth;
    std::array<double, 2> jogging = m_jogSpeed;
    jogging[az ? 0 : 1] = degreesPerSecond;
    // A frame sets both axes: one not jogging holds where it is.
    const double a = jogging[0] != 0.0 ? jogLegEnd(true, jogging[0]) : m_az;
    const double e = isAzimuthOnly() ? elevationOffset() : (jogging[1] != 0.0 ? jogLegEnd(false, jogging[1]) : m_el);
    const double moving = az ? a : e, from = az ? m_az : m_el;
    if (std::abs(moving - from) < 1.0) // within a degree of it: nothing a jog would do
        return refuseMove(tr("the %1 is at the end of its travel that way").arg(az ? tr("azimuth") : tr("elevation")));
    const model::MoveCheck check = m_gate.mechanical(a, e);
    if (!check.allowed())
        return refuseMove(check.refusal);
    if (const CommandResult sent = sendSetPosition(a, e); !sent)
        return sent;
    m_jogSpeed = jogging;     // sendSetPosition ended every jog; these go on
    m_jogLeg = {a, e};
    m_activeTarget.reset();   // running to an end, towards no target of the operator's
    return {};
}

void RotatorSession::continueJogLegs()
{
    // Called with each position: a leg nearly run out, and short of the
    // travel's end, is followed by the next.
    for (int i : {0, 1}) {
        if (m_jogSpeed[size_t(i)] == 0.0)
            continue;
        const double here = i == 0 ? m_az : m_el;
        const double next = jogLegEnd(i == 0, m_jogSpeed[size_t(i)]);
        if (std::abs(m_jogLeg[size_t(i)] - here) < kJogLegRenewDeg && std::abs(next - m_jogLeg[size_t(i)]) > 1.0) {
            jogBySetPosition(i == 0 ? Axis::Azimuth : Axis::Elevation, m_jogSpeed[size_t(i)]);
            return; // one frame sets both axes
        }
    }
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
    const QByteArray line = protocol::encodeStop(az, el, m_profile.dialect, m_rotor);
    if (line.isEmpty())
        return refuse(tr("%1 has no stop command").arg(protocol::dialectName(m_profile.dialect)));
    m_activeTarget.reset();
    write(line);
    m_refusals.noteCommand(line, nowMs());
    wakePolling(); // to see it come to rest
    emit stopSent(cause);
    emit targetCleared();
    // A SPID stop halts every axis: one still held on the jog pad runs on.
    if (protocol::isSpid(m_profile.dialect)) {
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
    if (!protocol::encodeStopHold(az, el, m_profile.dialect).isEmpty()) {
        m_holdAzimuth = az || (m_stopHoldTimer.isActive() && m_holdAzimuth);
        m_holdElevation = el || (m_stopHoldTimer.isActive() && m_holdElevation);
        m_stopHoldTimer.start(kStopHoldDelayMs);
    }
    return {};
}

void RotatorSession::sendStopHold()
{
    write(protocol::encodeStopHold(m_holdAzimuth, m_holdElevation, m_profile.dialect));
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
    if (!protocol::dialectSupports(m_profile.dialect, Op::Park) || !firmwareTraits().parkCommand) {
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
    m_jogSpeed = {0.0, 0.0};
    writeMove(protocol::encodeLine({Message::query(Op::Park)}, m_profile.dialect));
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
    if (!protocol::dialectSupports(m_profile.dialect, Op::Reset))
        return refuse(tr("%1 has no RESET (homing) command").arg(protocol::dialectName(m_profile.dialect)));
    // Homing runs each axis to its lower limit switch: the controller's own
    // move, bounded by the switches rather than by soft limits.
    m_jogSpeed = {0.0, 0.0};
    writeMove(protocol::encodeLine({Message::query(Op::Reset)}, m_profile.dialect));
    m_activeTarget.reset();
    // Homing ends at the lower limits: that is where the rotator is going
    // now, not the last go-to.
    m_targetAz = m_profile.limits.azMin + azimuthOffset();
    m_targetEl = m_profile.limits.elMin + elevationOffset();
    emit targetChanged(m_targetAz, m_targetEl);
    return {};
}

CommandResult RotatorSession::readConfig(int reg)
{
    if (auto linked = requireLink(); !linked)
        return linked;
    if (!protocol::dialectSupports(m_profile.dialect, Op::ConfigRead))
        return refuse(tr("%1 has no config registers").arg(protocol::dialectName(m_profile.dialect)));
    if (reg < 0 || reg > 99999)
        return refuse(tr("register %1 does not exist").arg(reg));
    Request r;
    r.line = protocol::encodeLine({Message::query(Op::ConfigRead, reg)}, m_profile.dialect);
    r.expects[0] = Expectation{Op::ConfigRead, reg};
    r.expectCount = 1;
    r.attemptsLeft = m_options.retries + 1;
    r.purpose = RequestPurpose::User;
    r.done = [this, line = printable(r.line)](bool ok, const QString &reason) {
        if (!ok)
            emit requestFailed(line, reason);
    };
    if (m_queue.isFull())
        return refuse(tr("the controller is not keeping up: %1 requests already waiting").arg(m_queue.size()));
    wakePolling();
    enqueue(std::move(r));
    return {};
}

CommandResult RotatorSession::writeConfig(int reg, const QString &value)
{
    if (auto linked = requireLink(); !linked)
        return linked;
    if (!protocol::dialectSupports(m_profile.dialect, Op::ConfigWrite))
        return refuse(tr("%1 has no config registers").arg(protocol::dialectName(m_profile.dialect)));
    if (reg < 0 || reg > 99999)
        return refuse(tr("register %1 does not exist").arg(reg));
    const QByteArray text = value.trimmed().toLatin1();
    if (text.isEmpty() || text.size() > 28)
        return refuse(tr("a register value is 1 to 28 characters"));
    for (char c : text) {
        if (c <= ' ' || c > '~' || c == ',' || c == ';')
            return refuse(tr("register value '%1' has a character the protocol cannot carry").arg(value));
    }
    if (reg == 7 || reg == 8) {
        // Park position: a value outside the limits would park into an end stop.
        const std::optional<double> angle = input::finiteNumber(value);
        if (!angle)
            return refuse(tr("park position must be a finite number"));
        const model::MoveCheck check = previewParkRegister(reg, *angle);
        if (!check.allowed())
            return refuseMove(check.refusal);
    }
    write(protocol::encodeLine({Message::word(Op::ConfigWrite, text, reg)}, m_profile.dialect));
    wakePolling();
    return {};
}

bool RotatorSession::isRawMove(const Message &m)
{
    switch (m.op) {
    case Op::Azimuth:
    case Op::Elevation:
        return m.hasValue;
    case Op::VelocityLeft:
    case Op::VelocityRight:
    case Op::VelocityUp:
    case Op::VelocityDown:
        return m.hasValue && m.value != 0.0;
    case Op::Offset:
    case Op::MoveLeft:
    case Op::MoveRight:
    case Op::MoveUp:
    case Op::MoveDown:
    case Op::Park:
    case Op::Preset:
        return true;
    default:
        return false;
    }
}

bool RotatorSession::awaitingPosition() const
{
    // A controller that can report its position and has not: its replies
    // are unreadable (often the wrong dialect), so nothing confirms where
    // a move would start, whether it runs, or when it ends. Easycomm I
    // cannot be asked at all, and is driven as it always was.
    return !m_positionReadOnLink && !protocol::encodeQueryPosition(m_profile.dialect, m_rotor).isEmpty();
}

QString RotatorSession::positionNotRead() const
{
    if (!awaitingPosition())
        return {};
    return m_caps.probed && !m_caps.positionFeedback
        ? tr("no position read from the controller: check the dialect (%1)").arg(protocol::dialectName(m_profile.dialect))
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

QString RotatorSession::rawMoveRefusal(const Message &m) const
{
    // rotctld takes a whole line as one command, and does more than Slew
    // reads (`w` passes bytes to the rotator): only the commands Slew reads
    // may go, each through the gate below.
    if (m_profile.dialect == Dialect::Rotctld && (m.op == Op::Invalid || m.op == Op::Report || !m.text.isEmpty()))
        return tr("'%1' is not a rotctld command Slew can check").arg(QString::fromLatin1(m.text.view().toByteArray()));
    // A GS-232 line that starts like a relative move but does not read as
    // one might still move a lenient controller by an amount nobody checked.
    if (protocol::isGs232(m_profile.dialect) && m.op == Op::Invalid && !m.text.isEmpty()
        && (m.text.view()[0] == 'O' || m.text.view()[0] == 'o'))
        return tr("'%1' is not a relative move Slew can check (O+010-005)")
            .arg(QString::fromLatin1(m.text.view().toByteArray()));
    // Micro-2g (docs/protocol.md): Mqqq is a bearing the program reaches the
    // short way, so it is checked as one; a preset goes to a bearing only
    // the controller knows, which is safe only where every bearing is.
    if (m_profile.dialect == Dialect::Micro2g) {
        if (m.op == Op::Azimuth && m.hasValue)
            return m_gate.azimuthBearing(m.value + azimuthOffset(), knownAzimuth()).refusal;
        // A go-to or preset that does not read (M400, X4rM, P9) might still
        // turn a lenient controller somewhere nobody checked.
        if (m.op == Op::Invalid && !m.text.isEmpty()) {
            const char c = m.text.view()[0];
            if (c == 'M' || c == 'm' || c == 'X' || c == 'x' || c == 'P' || c == 'p')
                return tr("'%1' is not a Micro-2g go-to Slew can check (M035, P1)")
                    .arg(QString::fromLatin1(m.text.view().toByteArray()));
        }
        if (m.op == Op::Preset) {
            const model::RotatorLimits l = m_gate.limits();
            if (l.azMax - l.azMin < 360.0)
                return tr("a Micro-2g preset goes to a bearing only the controller knows, and the limits "
                          "(%1°..%2°) do not allow every bearing")
                    .arg(l.azMin, 0, 'f', 0)
                    .arg(l.azMax, 0, 'f', 0);
        }
        return {};
    }
    // Angles in a raw line are the controller's own positions, sent as
    // typed (the gate sees them with the calibration offsets added); speeds
    // and bare moves drive towards a limit, as a jog does.
    switch (m.op) {
    case Op::Azimuth:
        return m.hasValue ? m_gate.azimuthPosition(m.value + azimuthOffset()).refusal : QString();
    case Op::Elevation:
        return m.hasValue ? m_gate.elevation(m.value + elevationOffset()).refusal : QString();
    case Op::Offset: {
        // GS-232's `O+aaa-eee`, sent as typed: the controller adds it to
        // where it is, which the session knows as the last position read.
        if (!hasPosition())
            return tr("a relative move needs the present position, which is not known yet");
        return m.index == 0 ? m_gate.azimuthPosition(m_az + m.value).refusal
                            : m_gate.elevation(m_el + m.value).refusal;
    }
    case Op::VelocityLeft:
    case Op::VelocityRight:
    case Op::VelocityUp:
    case Op::VelocityDown:
        if (!m.hasValue || m.value == 0.0)
            return {}; // a zero speed holds the axis
        [[fallthrough]];
    case Op::MoveLeft:
    case Op::MoveRight:
    case Op::MoveUp:
    case Op::MoveDown: {
        const bool az = m.op == Op::VelocityLeft || m.op == Op::VelocityRight || m.op == Op::MoveLeft
            || m.op == Op::MoveRight;
        const bool positive = m.op == Op::VelocityRight || m.op == Op::VelocityUp || m.op == Op::MoveRight
            || m.op == Op::MoveUp;
        const std::optional<double> at = hasPosition() ? std::optional<double>(az ? m_az : m_el) : std::nullopt;
        return m_gate.drive(az, positive, at).refusal;
    }
    case Op::Park: {
        const model::MoveCheck check = m_gate.mechanical(parkAzimuth(), parkElevation());
        return check.allowed() ? QString() : tr("the park position: %1").arg(check.refusal);
    }
    case Op::ConfigWrite:
        if (m.index == 7 || m.index == 8) {
            const std::optional<double> angle = input::finiteNumber(QString::fromLatin1(m.text.view()));
            if (!angle)
                return tr("park position must be a finite number");
            return previewParkRegister(m.index, *angle).refusal;
        }
        return {};
    default:
        return {};
    }
}

CommandResult RotatorSession::sendRaw(const QString &line)
{
    if (auto linked = requireLink(); !linked)
        return linked;
    // A SPID controller reads binary frames, which no printable line can
    // be: text would only be garbage on its wire.
    if (protocol::isSpid(m_profile.dialect))
        return refuse(tr("%1 speaks binary frames: raw text lines are not sent (use Go to, Stop and the jog pad)")
                          .arg(protocol::dialectName(m_profile.dialect)));
    const QByteArray bytes = line.trimmed().toLatin1();
    if (bytes.isEmpty())
        return refuse(tr("nothing to send"));
    if (bytes.size() > kMaxRawLine)
        return refuse(tr("a raw line is at most %1 characters").arg(kMaxRawLine));
    for (char c : bytes) {
        if (c < ' ' || c > '~')
            return refuse(tr("a raw line may hold printable ASCII only"));
    }
    // Raw lines pass the same gate as every other move, and a query goes
    // out even when no position has been read: it is how to find out why.
    QString error;
    protocol::Parser check(m_profile.dialect);
    const QString blind = requirePositionRead(Report::Quietly).refusal;
    check.feed(bytes + '\n', [&](const Message &m) {
        if (error.isEmpty() && !blind.isEmpty() && isRawMove(m))
            error = blind;
        if (error.isEmpty())
            error = rawMoveRefusal(m);
    });
    if (error.isEmpty() && check.hasUnfinishedLine())
        error = tr("'%1' is not a whole command").arg(line.trimmed()); // rotctld: a lone number
    if (!error.isEmpty())
        return refuseMove(error);
    writeMove(bytes + '\n');
    m_activeTarget.reset(); // a raw line may send the rotator anywhere, or stop it
    return {};
}

} // namespace slew::session
