// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// CCSDS OMM in keyword = value notation (KVN): one line a keyword, an
// optional unit in brackets after the value ("15.5 [rev/day]"), COMMENT
// lines, and several messages in one file, each starting at its
// CCSDS_OMM_VERS line (or, in files that leave that line out, where a
// keyword comes a second time).

#include "elementset.h"

#include <QByteArray>
#include <QDateTime>
#include <QList>
#include <QString>

namespace slew::sky {

ElementSetRead readOmmKvn(const QString &text);

// One message a set, a blank line between them, created at `created`.
QByteArray ommKvnText(const QList<ElementSet> &sets, const QDateTime &created);

} // namespace slew::sky
