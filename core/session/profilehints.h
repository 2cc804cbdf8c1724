// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A rotator profile with what a link says of its far end before connecting
// (transport::LinkHints): a window connected to `sim:?az_max=450` shows a
// 450° rotator and speaks the simulator's dialect. Hints the profile cannot
// take (an unknown dialect name, limits that would not validate) are left out.

#include "model/rotatorprofile.h"
#include "transport/link.h"

namespace slew::session {

model::RotatorProfile profileWithHints(model::RotatorProfile profile, const transport::LinkHints &hints);

// Empty when the dialect and firmware a URI names (`dialect=`, `firmware=`)
// are ones Slew knows and go together, else what is wrong: "unknown dialect
// 'yaesu' (known: easycomm1, ...)", "k3ng speaks easycomm2, gs232a or
// gs232b, not satnogs". The session opens no link whose URI says so.
QString hintNamesProblem(const transport::LinkHints &hints);

// The dialect and firmware the URI itself names, for the programs that take
// a URI and perhaps --dialect (slewctl, slew --headless): a rotctld:// peer
// speaks rotctld whatever else is said; `dialect=` (or a simulator's own)
// is taken unless the operator named a dialect otherwise, and `firmware=`
// (or a simulator's) where it can speak the dialect in force.
model::RotatorProfile profileNamedByUri(model::RotatorProfile profile, bool operatorNamedDialect);

} // namespace slew::session
