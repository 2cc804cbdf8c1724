// SPDX-License-Identifier: GPL-3.0-or-later
#include "codec.h"

#include "encoder.h"
#include "linecodec.h"
#include "spidframecodec.h"

#include <QObject>

namespace slew::protocol {

std::unique_ptr<Codec> Codec::forDialect(Dialect d, int rotor)
{
    switch (dialectRow(d).framing) {
    case Framing::SpidFrames:
        return std::make_unique<SpidFrameCodec>(d, rotor);
    case Framing::Lines:
        break;
    }
    return std::make_unique<LineCodec>(d, rotor);
}

Encoded Codec::setAxis(bool azimuth, double degrees) const
{
    const Message m = Message::number(azimuth ? Op::Azimuth : Op::Elevation, degrees);
    Encoded e;
    if (!setsBothAxes())
        e.bytes = encodeLine({m}, m_dialect);
    if (e.bytes.isEmpty())
        e.refusal = QObject::tr("%1 sets both axes at once").arg(name());
    return e;
}

QByteArray Codec::stop(bool azimuth, bool elevation) const
{
    return encodeStop(azimuth, elevation, m_dialect, m_rotor);
}

QByteArray Codec::stopHold(bool azimuth, bool elevation) const
{
    return encodeStopHold(azimuth, elevation, m_dialect);
}

QByteArray Codec::queryPosition() const
{
    return encodeQueryPosition(m_dialect, m_rotor);
}

int Codec::positionReplyBytes() const
{
    return protocol::positionReplyBytes(m_dialect);
}

QByteArray Codec::line(std::initializer_list<Message> messages) const
{
    return encodeLine(messages, m_dialect);
}

QString Codec::rawLineRefusal(const Message &) const
{
    return {};
}

} // namespace slew::protocol
