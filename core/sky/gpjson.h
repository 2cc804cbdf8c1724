// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// GP data as JSON: an array of objects keyed by the OMM keywords, as
// CelesTrak (numbers as JSON numbers) and Space-Track (every value a
// string, null for none) both serve it; a single object is read as one
// set. Keys Slew does not read are passed over. A refusal names the
// object's place in the array ("entry 3"), as JSON has no lines to name.

#include "elementset.h"

#include <QByteArray>
#include <QList>

namespace slew::sky {

ElementSetRead readGpJson(const QByteArray &bytes);

// An array of objects, one a set, numbers as numbers (CelesTrak's form).
QByteArray gpJsonText(const QList<ElementSet> &sets);

} // namespace slew::sky
