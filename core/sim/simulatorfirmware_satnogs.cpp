// SPDX-License-Identifier: GPL-3.0-or-later
// The SatNOGS rotator firmware v2.2, as it answers on the wire
// (docs/protocol.md, "Controllers in the field"), where Slew's own reading
// of the SatNOGS dialect is tidier: its status has no moving bit, and it
// reads a register number by its first digit. Its RS485 turn-around is the
// connection's (simulatorconnection.cpp), as it is a property of the line.

#include "simulatorfirmware.h"

namespace slew::sim {

int SimulatorFirmware::registerRead(int asked) const
{
    if (m_firmware != Firmware::SatNogs)
        return asked;
    // `CR10` is read as register 1 (and answered `1,8.00`): CR10..CR13 do
    // not exist in this firmware.
    while (asked >= 10)
        asked /= 10;
    return asked;
}

int SimulatorFirmware::combinedStatus() const
{
    const int bits = m_rotator.combinedStatus();
    if (m_firmware != Firmware::SatNogs)
        return bits;
    // Moving towards a target it says "pointing" (4) for the whole move and
    // never "moving" (2), as it does holding the position it reached; so
    // the word cannot tell a move from its end. Idle and errors as they are.
    if (bits == AxisStatus::Moving)
        return AxisStatus::Pointing;
    return bits;
}

void SimulatorFirmware::stopAxis(Axis axis)
{
    const bool azimuth = axis == Axis::Azimuth;
    // The SatNOGS firmware stops an axis by making where it is when SA or SE
    // is read its new set point: the axis, still turning, runs past it and
    // is driven back to it. Elsewhere a stop lets go of the drive (a worm
    // gear halts, a free drive coasts), as does a hold it cannot take.
    if (m_firmware == Firmware::SatNogs) {
        const double here = m_rotator.axis(axis).position();
        if (azimuth ? m_rotator.pointAzimuth(here) : m_rotator.pointElevation(here))
            return;
    }
    if (azimuth)
        m_rotator.stopAzimuth();
    else
        m_rotator.stopElevation();
}

} // namespace slew::sim
