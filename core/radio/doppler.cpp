// SPDX-License-Identifier: GPL-3.0-or-later
#include "doppler.h"

#include "sky/observation.h"

#include <cmath>

namespace slew::radio {

double downlinkOnGroundHz(double satelliteHz, double rangeRateKmS)
{
    return satelliteHz * sky::dopplerFactor(rangeRateKmS);
}

double uplinkToSendHz(double satelliteHz, double rangeRateKmS)
{
    return satelliteHz / sky::dopplerFactor(rangeRateKmS);
}

RadioTuning tuningFor(const SatelliteFrequencies &satellite, double rangeRateKmS)
{
    RadioTuning tuning;
    const double down = satellite.downlinkHz + satellite.downlinkOffsetHz;
    const bool correctDown = satellite.correct != DopplerOn::UplinkOnly;
    tuning.receiveHz = correctDown ? downlinkOnGroundHz(down, rangeRateKmS) : down;
    if (satellite.uplinkHz) {
        const double up = *satellite.uplinkHz + satellite.uplinkOffsetHz;
        const bool correctUp = satellite.correct != DopplerOn::DownlinkOnly;
        tuning.transmitHz = correctUp ? uplinkToSendHz(up, rangeRateKmS) : up;
    }
    return tuning;
}

double quantised(double hz, double stepHz)
{
    if (!(stepHz > 1.0))
        return std::round(hz);
    return std::round(hz / stepHz) * stepHz;
}

} // namespace slew::radio
