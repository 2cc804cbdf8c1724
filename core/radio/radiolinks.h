// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Making a RadioLink from a URI, the way transport/linkfactory.h makes a
// rotator link:
//
//   rigctld://host:port     a running rigctld (port 4532 when not given)
//
// libhamlib in process and the controller's UP/DN come later. A malformed
// URI, a missing host or an unknown scheme gives no link and a message
// that names the URI and the cause.

#include "radiolink.h"

#include <QString>

#include <memory>

namespace slew::radio {

// The link, unopened; null with *error set (when given) otherwise.
std::unique_ptr<RadioLink> makeRadioLink(const QString &uri, QString *error);

} // namespace slew::radio
