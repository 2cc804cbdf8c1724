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

} // namespace slew::session
