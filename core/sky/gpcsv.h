// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// CelesTrak's CSV form of GP data (its default since catalogue numbers
// passed five digits) and Space-Track's: a header row of OMM keywords, then
// one row a set. The header decides which column is which, in any order;
// columns Slew does not read are passed over. Quoted fields (with "" for a
// quote), CRLF or LF line ends and a UTF-8 byte-order mark are read as
// RFC 4180 has them.

#include "elementset.h"

#include <QByteArray>
#include <QList>
#include <QString>

namespace slew::sky {

ElementSetRead readGpCsv(const QString &text);

// CelesTrak's header and one row a set, numbers in the fewest digits that
// read back to the same value.
QByteArray gpCsvText(const QList<ElementSet> &sets);

} // namespace slew::sky
