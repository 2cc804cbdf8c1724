// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The pass-record database's tables, version by version. The version is
// kept in SQLite's user_version, and application_id marks the file as
// Slew's, so another program's database is not taken for an empty one.
//
//   1  passes (the pass, its figures, how it ended) and pass_samples (the
//      antenna's path and the target's, with the error between them)
//   2  passes gains doppler_rms_hz and doppler_worst_hz: the radio's
//      Doppler error over the pass
//
// A file of an older version is brought up to date in one transaction when
// a store opens it to record; a newer one is refused.

#include <QStringList>

namespace slew::records::schema {

inline constexpr int kCurrentVersion = 2;
// 'Slew' in ASCII.
inline constexpr int kApplicationId = 0x536c6577;

// The statements that make a database of `version` (1..kCurrentVersion)
// from nothing, user_version and application_id included. Tests build
// an old file with them.
QStringList create(int version);

// The statements that take a database from `from` to `from + 1`,
// user_version included.
QStringList upgrade(int from);

// The columns of passes a reader of `version` selects, in the order
// PassRecordStore reads them: a column the version lacks reads as NULL.
QString passColumns(int version);

} // namespace slew::records::schema
