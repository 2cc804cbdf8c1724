// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The URIs of the in-process Hamlib radio link (hamlibradio.h), read into
// what the link needs to open the radio:
//
//   hamlib:3081?device=/dev/ttyUSB0&baud=19200&civaddr=0xA2
//       Hamlib model 3081 (an IC-9700 in Hamlib 4.5.4; `rigctl -l` lists
//       them) on a serial line. `device` is needed for a serial model and
//       refused for any other; `baud` is one of the rates Hamlib sets on a
//       serial line (its default: the model's fastest); `civaddr` (0x01 to
//       0xDF, or decimal) only for a model that takes a CI-V address.
//   hamlib:1
//       a model without a serial line, such as Hamlib's dummy rig.
//   sim:
//       Hamlib's dummy rig (model 1): the built-in radio, which works with
//       nothing attached, as the rotator's sim: does. No options.
//
// Everything is checked here, before a link exists: an unknown model
// number, an option the model cannot take, an unknown option, a value out
// of range. The refusal says why; the caller puts the URI in front.

#include <QString>
#include <QUrl>

#include <optional>

namespace slew::radio {

struct HamlibRadioConfig {
    QString uri;        // as given, trimmed; "sim:" for the built-in radio
    int model = 0;      // Hamlib's model number
    QString modelName;  // "Icom IC-9700", for messages
    QString device;     // the serial line; empty for a model without one
    int baud = 0;       // 0: Hamlib's default for the model
    int civAddress = 0; // 0: the model's own
};

// Hamlib's dummy rig, which sim: opens.
inline constexpr int kHamlibDummyModel = 1;

// `url` as read from `uri`, whose scheme is hamlib or sim. Nothing, with
// *why set, when it cannot make a link.
std::optional<HamlibRadioConfig> hamlibRadioConfig(const QUrl &url, const QString &uri, QString *why);

} // namespace slew::radio
