// SPDX-License-Identifier: GPL-3.0-or-later
#include "linecodec.h"

#include "encoder.h"

#include <QObject>

#include <cmath>

namespace slew::protocol {

bool LineCodec::jogsItself() const
{
    return supports(Op::VelocityLeft) || supports(Op::MoveLeft);
}

Encoded LineCodec::setPosition(double azimuth, double elevation) const
{
    Encoded e;
    e.bytes = encodeSetPosition(azimuth, elevation, dialect(), rotor());
    if (e.bytes.isEmpty())
        e.refusal = QObject::tr("%1 has no command to set a position").arg(name());
    return e;
}

double LineCodec::setResolutionDeg() const
{
    return std::pow(10.0, -row().angleDecimals);
}

Encoded LineCodec::jog(const std::array<double, 2> &degreesPerSecond, bool changedIsAzimuth) const
{
    const double speed = degreesPerSecond[changedIsAzimuth ? 0 : 1];
    const bool positive = speed > 0;
    const Op velocityOp = changedIsAzimuth ? (positive ? Op::VelocityRight : Op::VelocityLeft)
                                           : (positive ? Op::VelocityUp : Op::VelocityDown);
    const Op moveOp = changedIsAzimuth ? (positive ? Op::MoveRight : Op::MoveLeft)
                                       : (positive ? Op::MoveUp : Op::MoveDown);
    Encoded e;
    if (supports(velocityOp)) {
        // Easycomm III's speeds are in thousandths of a degree a second.
        const Message m = Message::number(velocityOp, std::round(std::abs(speed) * 1000.0));
        e.bytes = encodeLine({m}, dialect());
        e.echo = m;
    } else if (supports(moveOp)) {
        e.bytes = encodeLine({Message::query(moveOp)}, dialect()); // runs at the controller's own speed
    }
    if (e.bytes.isEmpty())
        e.refusal = QObject::tr("%1 has no command to move an axis").arg(name());
    return e;
}

namespace {

QString textOf(const Message &m)
{
    return QString::fromLatin1(m.text.view().toByteArray());
}

bool startsWithOneOf(const Message &m, const char *letters)
{
    if (m.text.isEmpty())
        return false;
    const char c = m.text.view()[0];
    for (const char *l = letters; *l; ++l) {
        if (c == *l)
            return true;
    }
    return false;
}

} // namespace

QString LineCodec::rawLineRefusal(const Message &m) const
{
    switch (row().family) {
    case DialectFamily::Rotctld:
        // rotctld takes a whole line as one command, and does more than Slew
        // reads (`w` passes bytes to the rotator): only the commands Slew
        // reads may go, each through the gate.
        if (m.op == Op::Invalid || m.op == Op::Report || !m.text.isEmpty())
            return QObject::tr("'%1' is not a rotctld command Slew can check").arg(textOf(m));
        return {};
    case DialectFamily::Gs232:
        // A line that starts like a relative move but does not read as one
        // might still move a lenient controller by an amount nobody checked.
        if (m.op == Op::Invalid && startsWithOneOf(m, "Oo"))
            return QObject::tr("'%1' is not a relative move Slew can check (O+010-005)").arg(textOf(m));
        return {};
    case DialectFamily::Micro2g:
        // A go-to or preset that does not read (M400, X4rM, P9) might still
        // turn a lenient controller somewhere nobody checked.
        if (m.op == Op::Invalid && startsWithOneOf(m, "MmXxPp"))
            return QObject::tr("'%1' is not a Micro-2g go-to Slew can check (M035, P1)").arg(textOf(m));
        return {};
    case DialectFamily::Easycomm:
    case DialectFamily::Spid:
        break;
    }
    return {};
}

} // namespace slew::protocol
