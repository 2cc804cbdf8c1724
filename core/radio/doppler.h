// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Doppler for a satellite's radio, from the range-rate the tracker already
// computes (sky/observation.h: positive while the satellite recedes).
//
//   downlink heard on the ground:  f_ground = f_sat · (1 − ṙ/c)
//   uplink to send from the ground: f_send  = f_sat / (1 − ṙ/c)
//
// so that the satellite hears its nominal uplink. First order in ṙ/c; the
// relativistic term is 1e-10, a tenth of a hertz at 1 GHz.

#include <optional>

namespace slew::radio {

// Which of the two frequencies Slew corrects (gpredict#202 asks for the
// uplink alone: some operators tune the downlink by ear).
enum class DopplerOn { Both, DownlinkOnly, UplinkOnly };

// How the uplink follows when the operator turns the downlink on the dial:
// not at all (a fixed channel), the same way (a non-inverting linear
// transponder), or the opposite way (an inverting one, as most are).
enum class UplinkFollowsDial { No, SameWay, OppositeWay };

// A linear transponder's downlink passband (at the satellite), Hz.
struct Passband {
    double lowHz = 0;
    double highHz = 0;
};

// What the satellite sends and listens on, with the operator's calibration
// offsets (a satellite's crystal drifts with age and temperature), in Hz.
struct SatelliteFrequencies {
    double downlinkHz = 0;               // what the satellite transmits
    std::optional<double> uplinkHz;      // what it listens on, if anything
    double downlinkOffsetHz = 0;         // added to downlinkHz (calibration)
    double uplinkOffsetHz = 0;           // added to uplinkHz
    DopplerOn correct = DopplerOn::Both;
    UplinkFollowsDial uplinkFollows = UplinkFollowsDial::No;
    // Where the operator may tune the downlink from the window: the linear
    // transponder's passband it lies in; none when not known (a single
    // frequency, or one typed by hand for a satellite with no transponder
    // list), and the window's steps are then not bounded.
    std::optional<Passband> downlinkPassband;
};

// What to tune the radio to: receive and, with an uplink, transmit.
struct RadioTuning {
    double receiveHz = 0;
    std::optional<double> transmitHz;
};

double downlinkOnGroundHz(double satelliteHz, double rangeRateKmS);
double uplinkToSendHz(double satelliteHz, double rangeRateKmS);

// The radio's frequencies for a satellite at range-rate ṙ (km/s).
RadioTuning tuningFor(const SatelliteFrequencies &satellite, double rangeRateKmS);

// The nearest multiple of `stepHz` (≤ 1 Hz: to the hertz).
double quantised(double hz, double stepHz);

} // namespace slew::radio
