// SPDX-License-Identifier: GPL-3.0-or-later
// K3NG's Arduino rotator firmware, as its own source answers in its Easycom
// emulation (docs/protocol.md, "Controllers in the field"): every token is
// a command of its own, acted on when the space, CR or LF after it arrives;
// its answer goes out followed by that same byte, so `AZ EL\n` is answered
// `+59.1 +24.8\n` and a set `AZ94.0 EL25.0\n` by its separators alone. It
// knows AZ, EL, ML, MR, MU, MD, SA, SE and VE; to anything else it says `?`.
// Its Yaesu emulation is the GS-232 firmware's, with the report joined
// (reportSeparator below) and `?>` for what it lacks, as Slew's already.

#include "simulatorfirmware.h"

#include "protocol/encoder.h"

#include <cmath>

namespace slew::sim {

using protocol::Dialect;
using protocol::Message;
using protocol::Op;

namespace {

// dtostrf(value, 0, 1): one decimal; the azimuth with a '+' always, the
// elevation with a '+' when not negative.
QByteArray k3ngAngle(double degrees)
{
    return (degrees >= 0 ? "+" : "") + protocol::formatNumber(degrees, 1);
}

// Where K3NG's relay lets go inside its 3° tolerance, short of the target.
constexpr double kK3ngStopsShortDegrees = 2.3;

} // namespace

bool SimulatorFirmware::pointAzimuth(double degrees)
{
    if (m_firmware != Firmware::K3ng)
        return m_rotator.pointAzimuth(degrees);
    // K3NG drives until the azimuth is within its AZIMUTH_TOLERANCE, then
    // lets go of the relay: a target already that close does not move it,
    // and a move ends short of the target, inside the tolerance (2.3° short,
    // as seen on its relays and potentiometer).
    const double tolerance = protocol::firmwareTraits(Firmware::K3ng).azToleranceDeg;
    const double az = m_rotator.axis(Axis::Azimuth).position();
    const AxisPlant &plant = m_rotator.axis(Axis::Azimuth).plant();
    if (!std::isfinite(degrees) || degrees < plant.minDegrees || degrees > plant.maxDegrees)
        return m_rotator.pointAzimuth(degrees); // refused there, as for any firmware
    if (std::abs(degrees - az) <= tolerance)
        return true;
    return m_rotator.pointAzimuth(degrees - std::copysign(kK3ngStopsShortDegrees, degrees - az));
}

bool SimulatorFirmware::speaksK3ngEasycom() const
{
    return m_firmware == Firmware::K3ng && m_dialect == Dialect::Easycomm2;
}

QByteArray SimulatorFirmware::reportSeparator() const
{
    // K3NG's GS-232B runs its two reports together: `AZ=059EL=025`.
    if (m_firmware == Firmware::K3ng && m_dialect == Dialect::Gs232B)
        return {};
    return protocol::reportSeparator(m_dialect);
}

void SimulatorFirmware::handleK3ngEasycom(const Message &m, QByteArray &out)
{
    QByteArray reply;
    const double az = m_rotator.axis(Axis::Azimuth).position();
    const double el = m_rotator.axis(Axis::Elevation).position();
    bool taken = true;
    switch (m.op) {
    case Op::Azimuth:
        if (!m.hasValue)
            reply = k3ngAngle(az);
        else
            taken = pointAzimuth(m.value);
        break;
    case Op::Elevation:
        if (!m.hasValue)
            reply = k3ngAngle(el);
        else
            taken = m_rotator.pointElevation(m.value);
        break;
    case Op::MoveLeft:
    case Op::MoveRight:
    case Op::MoveUp:
    case Op::MoveDown:
    case Op::StopAzimuth:
    case Op::StopElevation: manualMove(m.op); break;
    case Op::Version:
        if (m.text.isEmpty())
            reply = "VE002"; // "sending 002 because this is easycom version 2?", says its source
        else
            taken = false;
        break;
    default: taken = false; break;
    }
    if (taken) {
        ++m_counters.commands;
    } else {
        const bool angle = (m.op == Op::Azimuth || m.op == Op::Elevation) && m.hasValue;
        ++(angle ? m_counters.outOfLimits : m.isValid() ? m_counters.unknown : m_counters.malformed);
        reply = "?";
    }
    out += reply;
    out += m.lineEnd ? '\n' : ' ';
}

} // namespace slew::sim
