// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Two-line element sets: the fixed-column text of Spacetrack Report #3, two
// lines a set with an optional name line before them ("3LE"), catalogue
// numbers past 99999 in Alpha-5. Read into an ElementSet with the ranges of
// gpfields.h, and written from one for programs that read nothing else.

#include "elementset.h"

#include <QString>
#include <QStringView>

#include <optional>

namespace slew::sky {

// The modulo-10 checksum of a line's first 68 columns: digits count their
// value, '-' counts one, everything else nothing.
int tleChecksum(QStringView line);

// One set from its two element lines; the reason on refusal (line is 1 or 2).
// Checksums are always checked for real data; the published verification set
// deliberately carries some wrong ones, so its test may skip them.
bool parseTle(const QString &line1, const QString &line2, ElementSet *out, ElementSetRefusal *refusal,
              bool checkChecksums = true);

// A whole file or pasted text: two- and three-line sets, in any mix.
ElementSetRead readTleText(const QString &text);

// The set as three lines (the name first; two lines when it has none), each
// ending in '\n'; nothing, and *why, for a set a TLE cannot carry: a
// catalogue number above Alpha-5's 339999, or a value wider than its column.
// Values are rounded to the columns' digits, so reading the lines back and
// writing them again gives the same lines.
std::optional<QString> tleText(const ElementSet &set, QString *why);

} // namespace slew::sky
