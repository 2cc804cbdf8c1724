// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Whether a new copy of an element-set source may replace the cached one.
// A server that answers with a login page, a rate-limit notice holding one
// example set, or a transfer cut short still gives text that reads in part;
// taking it would throw away a good copy. So a new copy must read cleanly
// and keep most of the satellites the old copy had.

#include "elementset.h"

#include <QByteArray>
#include <QList>
#include <QString>

namespace slew::sky {

// At most one entry in ten may be refused (one is always allowed, so a
// short hand-written file with a typo still loads).
inline constexpr int kMaxRefusedPerTenSets = 1;
// At least half of the old copy's catalogue numbers must be in the new one.
inline constexpr double kMinShareOfOldSatellitesKept = 0.5;

// Why `fresh` (read from `text`) must not replace `previous`, or empty when
// it may. `previous` is empty when there is no old copy.
QString whyNotReplace(const QByteArray &text, const ElementSetRead &fresh, const QList<ElementSet> &previous);

} // namespace slew::sky
