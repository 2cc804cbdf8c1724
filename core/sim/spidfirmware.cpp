// SPDX-License-Identifier: GPL-3.0-or-later
#include "spidfirmware.h"

#include "protocol/encoder.h"

namespace slew::sim {

using protocol::Dialect;
using protocol::spid::Command;
using protocol::spid::Frame;
namespace MoveBit = protocol::spid::MoveBit;

SpidFirmware::SpidFirmware(SimulatedRotator &rotator, FirmwareCounters &counters, Dialect dialect,
                           const SpidSettings &settings)
    : m_rotator(rotator), m_counters(counters), m_dialect(dialect), m_settings(settings), m_parser(dialect)
{
}

QByteArray SpidFirmware::receive(QByteArrayView bytes)
{
    QByteArray out;
    m_parser.feed(bytes, [&](const Frame &f) { handle(f, out); });
    return out;
}

void SpidFirmware::handle(const Frame &f, QByteArray &out)
{
    switch (f.kind) {
    case Frame::Kind::Reply: // a controller's words sent to a controller
    case Frame::Kind::Text:
    case Frame::Kind::Skipped: ++m_counters.malformed; return;
    case Frame::Kind::Refused:
        ++(f.outOfRange ? m_counters.outOfLimits : m_counters.malformed);
        return;
    case Frame::Kind::Command: break;
    }
    ++m_counters.lines; // one frame is the binary protocol's line
    switch (f.command) {
    case Command::Status: break;
    case Command::Stop:
        m_rotator.stopAzimuth();
        m_rotator.stopElevation();
        break;
    case Command::Set:
        set(f);
        if (m_dialect != Dialect::Md01)
            return; // a Rot2Prog (and Rot1Prog) does not answer a set
        break;
    case Command::Move:
        move(f.moveDirections);
        return; // Hamlib reads nothing after a move
    }
    out += reply();
}

void SpidFirmware::set(const Frame &f)
{
    // The axis model's own limits (0..az_max, 0..el_max) are narrower than
    // the protocol's; what it refuses is counted, as a controller that
    // cannot reach an angle would ignore it.
    bool ok = m_rotator.pointAzimuth(f.azimuth);
    if (m_dialect != Dialect::Rot1Prog)
        ok = m_rotator.pointElevation(f.elevation) && ok;
    if (ok)
        ++m_counters.commands;
    else
        ++m_counters.outOfLimits;
}

void SpidFirmware::move(int directions)
{
    ++m_counters.commands;
    const double az = 1000.0 * m_rotator.axis(Axis::Azimuth).plant().manualSpeed;
    const double el = 1000.0 * m_rotator.axis(Axis::Elevation).plant().manualSpeed;
    if (directions & (MoveBit::Left | MoveBit::Right))
        m_rotator.driveAzimuth(directions & MoveBit::Left ? -az : az);
    if (directions & (MoveBit::Up | MoveBit::Down))
        m_rotator.driveElevation(directions & MoveBit::Down ? -el : el);
}

QByteArray SpidFirmware::reply()
{
    const double az = m_rotator.axis(Axis::Azimuth).position();
    const double el = m_dialect == Dialect::Rot1Prog ? 0.0 : m_rotator.axis(Axis::Elevation).position();
    QByteArray out;
    if (m_settings.logLines && m_dialect == Dialect::Md01) {
        // Text that starts with the frame's own start byte, 'W', to make
        // a reader that only looks for 0x57 stumble.
        out += "Wind-up check " + QByteArray::number(++m_logLines) + ": az " + protocol::formatNumber(az, 1) + "\r\n";
    }
    const int pulses = m_settings.pulsesPerDegree;
    out += protocol::spid::encodeReply(az, el, m_dialect, pulses, pulses);
    return out;
}

} // namespace slew::sim
