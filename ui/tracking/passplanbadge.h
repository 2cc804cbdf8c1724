// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How a pass's plan is shown in the pass tables (One target, Upcoming):
// "plain", "flip", "over the top, overlap", "lags 3.2°", or why there is no
// plan on this rotator.

#include "tracking/passplanner.h"

#include <QString>

namespace slew::ui {

QString passPlanBadge(const tracking::PassPlan &plan);

} // namespace slew::ui
