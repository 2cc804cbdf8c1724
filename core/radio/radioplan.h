// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What to tune a radio to for one satellite: its frequencies, the modes of
// each path, and where they came from. Made by hand (the service's
// --downlink and --uplink, the Radio panel) or from a transponder:
//
//   - a linear transponder is tuned to the middle of its passband, the
//     uplink paired with it (Transponder::uplinkForDownlink), and the
//     uplink follows the operator's dial the way the transponder maps it
//     (the opposite way when it inverts);
//   - a single-frequency transmitter (an FM repeater, a beacon) is tuned to
//     that frequency and its uplink, if any, which does not follow the dial;
//   - the modes: an SSB transponder is USB down and, inverting, LSB up
//     (non-inverting: USB up); FM, AM and CW are the same both ways; a mode
//     Hamlib has no name for (BPSK, GMSK, "SSTV") leaves the radio's mode
//     alone, as the note says.
//
// Also reads a frequency as an operator writes it: 145.8M, 435.125 MHz,
// 1296200k, 437800000 (hertz). Pure code.

#include "doppler.h"
#include "transponder.h"

#include <QList>
#include <QString>

#include <optional>

namespace slew::radio {

struct RadioPlan {
    SatelliteFrequencies frequencies;
    QString receiveMode;  // a Hamlib mode name (USB, FM, ...); empty: left as it is
    QString transmitMode; // with an uplink; empty: left as it is
    QString name;         // the transponder's, for messages; may be empty
    // The plan is for this satellite (NORAD number) only; 0: whatever is tracked.
    int noradId = 0;
};

// The plan for a transponder; *note (when given) says what was left to the
// operator (a mode with no Hamlib name). Nothing, with *error, for a
// transponder without a downlink.
std::optional<RadioPlan> planFor(const Transponder &transponder, QString *note, QString *error);

// The passband of the first linear transponder among `transponders` whose
// downlink passband holds `downlinkHz`; none when no such one is known.
std::optional<Passband> passbandAround(const QList<Transponder> &transponders, double downlinkHz);

// Hertz from "145.8M", "145.8 MHz", "1296200k", "10.368G" or a plain
// number of hertz ("437800000"); letter case aside. From 1 Hz to
// kHighestFrequencyHz. A plain number under 1 MHz is refused as a likely
// slip ("145.8" was meant as megahertz): write it with its unit.
std::optional<double> parseFrequency(const QString &text, QString *error);

// A Hamlib mode name: 1 to 8 letters or digits ("USB", "PKTUSB"), upper-cased.
std::optional<QString> parseModeName(const QString &text, QString *error);

// A calibration offset in hertz, signed, with the same units: "-1.2k",
// "350". Within ±1 MHz: a crystal drifts kilohertz, not more.
std::optional<double> parseFrequencyOffset(const QString &text, QString *error);

} // namespace slew::radio
