// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One telemetry sample as a station publishes it on `slew/NAME/telemetry`,
// at most at the rotator's poll rate: a flat JSON object with the values
// known now, each left out when unknown.
//
//   {"unix_ms":…, "az":120.1, "el":30.0, "commanded_az":…, "commanded_el":…,
//    "az_speed":5.9, "el_speed":0, "az_load":…, "el_load":…, "temperature":21.5,
//    "gs":1030, "ge":1, "pointing_error":0.12,
//    "doppler_rx_error":1.5, "doppler_tx_error":-0.4}
//
// Speeds in degrees a second, temperature in °C, errors in degrees and
// hertz; GS and GE as the controller's raw registers. Pure code.

#include "face/telemetrysample.h"

#include <QByteArray>
#include <QMetaType>

#include <optional>

namespace slew::remote {

inline constexpr int kLargestTelemetryMessage = 4096;

QByteArray encodeTelemetry(const face::TelemetrySample &sample);
std::optional<face::TelemetrySample> parseTelemetry(const QByteArray &payload, QString *error);

} // namespace slew::remote

