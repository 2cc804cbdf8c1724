// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A SPID controller's command interpreter (Rot2Prog, Rot1Prog, MD-01/02 in
// ROT2 mode): 13-byte command frames in, binary replies out, acting on the
// same SimulatedRotator (and so the same axis physics) as the line dialects.
//
// - status and stop are answered with the position (12 bytes, Rot1Prog 5);
// - a set is answered by the MD-01/02 only, with the position at once;
//   a plain Rot2Prog and a Rot1Prog stay silent, as Hamlib expects;
// - the MD-01/02 move (K 0x14) drives the named axes at the manual speed;
// - Rot1Prog has no elevation: its sets and replies carry azimuth alone;
// - with logLines the MD-01/02 writes a text log line ahead of every reply,
//   as some of its firmware does, so a host must find the frame after it.
// A frame the controller cannot act on is counted and not answered. No I/O.

#include "firmwarecounters.h"
#include "simulatedrotator.h"

#include "protocol/dialect.h"
#include "protocol/spidparser.h"

#include <QByteArray>

namespace slew::sim {

struct SpidSettings {
    int pulsesPerDegree = 2; // PH and PV in the replies: 1, 2, 4 or 10
    bool logLines = false;   // MD-01/02: a text line before every reply
};

class SpidFirmware {
public:
    SpidFirmware(SimulatedRotator &rotator, FirmwareCounters &counters, protocol::Dialect dialect,
                 const SpidSettings &settings);

    // Feeds bytes from the host; returns the replies they call for.
    QByteArray receive(QByteArrayView bytes);

private:
    void handle(const protocol::spid::Frame &f, QByteArray &out);
    void set(const protocol::spid::Frame &f);
    void move(int directions);
    QByteArray reply();

    SimulatedRotator &m_rotator;
    FirmwareCounters &m_counters;
    protocol::Dialect m_dialect;
    SpidSettings m_settings;
    protocol::spid::Parser m_parser;
    int m_logLines = 0; // how many log lines were written, for their text
};

} // namespace slew::sim
