// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A satellite's transponder or transmitter, as the Doppler steering and the
// Radio panel use it: its uplink and downlink (a single frequency, or a
// passband for a linear transponder), its mode, whether it inverts, and
// whether it still works. Pure code; the importers are in
// transponderimport.h.
//
// Frequencies are in hertz, as both sources give them. A side the
// satellite does not have (no uplink on a beacon) is empty. A single
// frequency has its low set and its high empty or equal to the low; a
// passband has both, low < high. The importers hold every value they let
// through to: finite, above 0, at most kHighestFrequencyHz, low <= high.

#include <QString>

#include <optional>

namespace slew::radio {

// Nothing a station tunes is above the top of the radio spectrum (300 GHz,
// where the ITU's allocations end); a larger figure is a corrupt entry.
inline constexpr double kHighestFrequencyHz = 300e9;

struct Transponder {
    int noradId = 0;
    QString description; // SatNOGS's description, or the Gpredict group name
    std::optional<double> uplinkLowHz;
    std::optional<double> uplinkHighHz;
    std::optional<double> downlinkLowHz;
    std::optional<double> downlinkHighHz;
    QString mode;        // as the source names it ("USB", "FM", "SSB/CW"); may be empty
    bool inverting = false;
    bool alive = true;
    QString uuid;        // SatNOGS DB's identity of the entry; empty from Gpredict

    // A passband on the downlink (low != high): a linear transponder, whose
    // uplink follows the downlink across it.
    bool isLinear() const;
    bool hasUplink() const { return uplinkLowHz.has_value(); }
    bool hasDownlink() const { return downlinkLowHz.has_value(); }
    // The downlink's top: the high edge, or the single frequency.
    std::optional<double> downlinkTopHz() const { return downlinkHighHz ? downlinkHighHz : downlinkLowHz; }
    // Whether `downlinkHz` lies in the downlink passband, edges included.
    bool downlinkContains(double downlinkHz) const;

    // For a linear transponder with an uplink: the uplink frequency (at the
    // satellite) that comes down at `downlinkHz`, both without Doppler.
    // The transponder maps its uplink passband onto its downlink one, the
    // same width, upside down when it inverts:
    //   inverting:      uplink = uplinkLow + (downlinkHigh - downlink)
    //   non-inverting:  uplink = uplinkLow + (downlink - downlinkLow)
    // Nothing when the transponder is not linear, has no uplink, or
    // `downlinkHz` is not a finite frequency inside the downlink passband:
    // past its edges there is no pairing, and a transmitter steered by an
    // extrapolation could leave the uplink band.
    std::optional<double> uplinkForDownlink(double downlinkHz) const;
    // The inverse: the downlink where an uplink at `uplinkHz` comes out.
    //   inverting:      downlink = downlinkHigh - (uplink - uplinkLow)
    //   non-inverting:  downlink = downlinkLow + (uplink - uplinkLow)
    // Nothing under the same conditions, for a result outside the downlink
    // passband included.
    std::optional<double> downlinkForUplink(double uplinkHz) const;

    // "FO-29 Mode V/U linear" as shown in messages: the description, or
    // "transponder" when it has none. Not escaped.
    QString displayName() const;
};

} // namespace slew::radio
