// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Making a RadioLink from a URI, the way transport/linkfactory.h makes a
// rotator link:
//
//   rigctld://host:port                   a running rigctld (port 4532 when not given)
//   hamlib:MODEL?device=/dev/ttyUSB0      libhamlib in this process: Hamlib's model
//                                         number, options baud and civaddr too (hamliburi.h)
//   sim:                                  Hamlib's dummy rig in this process: the
//                                         built-in radio, for trying Slew out
//
// The controller's UP/DN link (`controller`, controllerradio.h) is made
// from a rotator session, not here. A malformed URI, a missing host, an
// unknown model, option or scheme gives no link and a message that names
// the URI and the cause.

#include "radiolink.h"

#include <QString>

#include <memory>

namespace slew::radio {

// The link, unopened; null with *error set (when given) otherwise.
std::unique_ptr<RadioLink> makeRadioLink(const QString &uri, QString *error);

} // namespace slew::radio
