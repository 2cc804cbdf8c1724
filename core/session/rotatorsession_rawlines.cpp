// SPDX-License-Identifier: GPL-3.0-or-later
// RotatorSession's raw lines: a line the operator types for the
// controller goes only where the codec reads text, and only when what it
// would do is known and passes the same gate as every other move.

#include "rotatorsession.h"

#include "input/finitenumber.h"

namespace slew::session {

using protocol::Message;
using protocol::Op;

namespace {

constexpr int kMaxRawLine = 200;

} // namespace

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

QString RotatorSession::rawMoveRefusal(const Message &m) const
{
    // A line whose meaning the codec cannot vouch for (rotctld's other
    // commands, a GS-232 `O` or a Micro-2g go-to that does not read).
    if (const QString unreadable = m_codec->rawLineRefusal(m); !unreadable.isEmpty())
        return unreadable;
    // A preset goes to a bearing only the controller knows (Micro-2g's
    // Pnm), which is safe only where every bearing is.
    if (m.op == Op::Preset) {
        const model::RotatorLimits l = m_gate.limits();
        if (l.azMax - l.azMin < 360.0)
            return tr("a preset goes to a bearing only the controller knows, and the limits "
                      "(%1°..%2°) do not allow every bearing")
                .arg(l.azMin, 0, 'f', 0)
                .arg(l.azMax, 0, 'f', 0);
        return {};
    }
    // Angles in a raw line are the controller's own positions, sent as
    // typed (the gate sees them with the calibration offsets added); speeds
    // and bare moves drive towards a limit, as a jog does.
    switch (m.op) {
    case Op::Azimuth:
        if (!m.hasValue)
            return {};
        // Micro-2g's Mqqq is a bearing the program reaches the short way.
        return m_codec->azimuthIsBearing() ? m_gate.azimuthBearing(m.value + azimuthOffset(), knownAzimuth()).refusal
                                           : m_gate.azimuthPosition(m.value + azimuthOffset()).refusal;
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
    // A controller of binary frames reads no printable line: text would
    // only be garbage on its wire.
    if (!m_codec->readsTextLines())
        return refuse(tr("%1 speaks binary frames: raw text lines are not sent (use Go to, Stop and the jog pad)")
                          .arg(m_codec->name()));
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
    const std::unique_ptr<protocol::Codec> check = protocol::Codec::forDialect(m_codec->dialect(), m_rotor);
    const QString blind = requirePositionRead(Report::Quietly).refusal;
    check->feed(bytes + '\n', [&](const Message &m) {
        if (error.isEmpty() && !blind.isEmpty() && isRawMove(m))
            error = blind;
        if (error.isEmpty())
            error = rawMoveRefusal(m);
    });
    if (error.isEmpty() && check->hasUnfinishedInput())
        error = tr("'%1' is not a whole command").arg(line.trimmed()); // rotctld: a lone number
    if (!error.isEmpty())
        return refuseMove(error);
    writeMove(bytes + '\n');
    m_activeTarget.reset(); // a raw line may send the rotator anywhere, or stop it
    return {};
}

} // namespace slew::session
