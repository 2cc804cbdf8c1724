// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One telemetry sample of a station: the values known now, each left
// unset when unknown. Speeds in degrees a second, temperature in °C,
// errors in degrees and hertz; GS and GE as the controller's raw
// registers. Published on a broker as JSON (remote/stationtelemetry.h).

#include <QMetaType>

#include <optional>

namespace slew::face {

struct TelemetrySample {
    qint64 unixMs = 0;
    std::optional<double> az, el, commandedAz, commandedEl;
    std::optional<double> azSpeed, elSpeed, azLoad, elLoad, temperature;
    std::optional<int> gs, ge;
    std::optional<double> pointingError, dopplerRxError, dopplerTxError;
};

} // namespace slew::face

Q_DECLARE_METATYPE(slew::face::TelemetrySample)
