// SPDX-License-Identifier: GPL-3.0-or-later
#include "spidframecodec.h"

#include "spidcodec.h"

#include <QObject>

#include <algorithm>

namespace slew::protocol {

Encoded SpidFrameCodec::setPosition(double azimuth, double elevation) const
{
    // Guessing the resolution would send a Rot2Prog at 2 pulses a degree to
    // twice the angle; Rot1Prog's whole degrees need none.
    const int azPulses = m_parser.spidAzimuthPulses(), elPulses = m_parser.spidElevationPulses();
    Encoded e;
    if (dialect() != Dialect::Rot1Prog && (azPulses == 0 || elPulses == 0)) {
        e.refusal = QObject::tr("the controller's resolution is not known yet: it has not answered a status request");
        return e;
    }
    const spid::Encoded set = spid::encodeSet(azimuth, elevation, dialect(), azPulses, elPulses);
    e.bytes = set.bytes;
    if (!set.ok())
        e.refusal = QString::fromLatin1(set.refusal);
    return e;
}

double SpidFrameCodec::setResolutionDeg() const
{
    if (dialect() == Dialect::Rot1Prog)
        return 1.0; // whole degrees
    const int pulses = std::max(m_parser.spidAzimuthPulses(), m_parser.spidElevationPulses());
    return pulses > 0 ? 1.0 / pulses : 1.0;
}

Encoded SpidFrameCodec::jog(const std::array<double, 2> &degreesPerSecond, bool) const
{
    // The MD-01/02's move names every axis that is to run.
    namespace Bit = spid::MoveBit;
    int directions = 0;
    if (degreesPerSecond[0] != 0.0)
        directions |= degreesPerSecond[0] > 0 ? Bit::Right : Bit::Left;
    if (degreesPerSecond[1] != 0.0)
        directions |= degreesPerSecond[1] > 0 ? Bit::Up : Bit::Down;
    const spid::Encoded move = spid::encodeMove(directions, dialect());
    Encoded e;
    e.bytes = move.bytes;
    if (!move.ok())
        e.refusal = QString::fromLatin1(move.refusal);
    return e;
}

} // namespace slew::protocol
