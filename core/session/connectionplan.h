// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What connecting to a URI means for the rotator profile, decided here once
// for every face and program: the dialect the link speaks, the firmware's
// ways, what a simulator's URI says of its rotator, and the calibration
// found for that rotator before. A window connected to `sim:?az_max=450`
// shows a 450° rotator and speaks the simulator's dialect; a rotctld://
// peer speaks rotctld whatever else is said.
//
// The link says what it knows of its far end before connecting
// (transport::LinkHints); hints the profile cannot take (an unknown dialect
// name, limits that would not validate) are left out.

#include "model/rotatorprofile.h"
#include "protocol/dialect.h"
#include "transport/link.h"

namespace slew::session {

// The window's connection to `uri`: the dialect chosen in its list, unless
// the link names one (a simulator's URI, rotctld://), which the list then
// shows; a URI's travel and park; the calibration saved for this rotator,
// or none when it is another rotator than `connectedBefore` (one rotator
// does not inherit another's).
model::RotatorProfile windowConnectionProfile(const QString &uri, model::RotatorProfile current,
                                              protocol::Dialect chosen, const QString &connectedBefore);

// A program's (slewctl, slew --headless), its profile's URI already set: a
// rotctld:// peer speaks rotctld whatever else is said; the URI's
// `dialect=` (or a simulator's own) is taken unless the operator named a
// dialect (--dialect, --profile), and `firmware=` (or a simulator's) where
// it can speak the dialect in force. A program's travel is its --limits.
model::RotatorProfile commandLineConnectionProfile(model::RotatorProfile profile, bool operatorNamedDialect);

// The dialect a probe of `uri` asks in (the wizard): the one the link names,
// else the one chosen. A Micro-2g answers no Easycomm query at any baud rate.
protocol::Dialect probeDialect(const QString &uri, protocol::Dialect chosen);

// `profile` with all the link's hints taken: dialect, firmware, travel and
// park; past the dialect and firmware, all or nothing (half a rotator's
// travel is worse than the operator's own profile).
model::RotatorProfile profileWithHints(model::RotatorProfile profile, const transport::LinkHints &hints);

// Empty when the dialect and firmware a URI names (`dialect=`, `firmware=`)
// are ones Slew knows and go together, else what is wrong: "unknown dialect
// 'yaesu' (known: easycomm1, ...)", "k3ng speaks easycomm2, gs232a or
// gs232b, not satnogs". The session opens no link whose URI says so.
QString hintNamesProblem(const transport::LinkHints &hints);

} // namespace slew::session
