// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Whether a path may be opened as a pass-record database, decided before
// SQLite is given it: SQLite opens any file and only fails at the first
// read, and a file that is not a database must be refused whole and left
// as it is, never written to.

#include <QString>

namespace slew::records {

// The 16 bytes every SQLite 3 database file starts with.
inline constexpr char kSqliteHeader[] = "SQLite format 3";

enum class PassRecordFileKind {
    Absent,   // nothing there: a new database may be made
    Empty,    // a file of no bytes: SQLite takes it as a new database
    Database, // an SQLite database (whose tables are still to be checked)
    Unusable, // anything else; *why says what
};

// What is at `path`, read the careful way (input/boundedfile.h: a regular
// file only, its first bytes only). *why names the file.
PassRecordFileKind inspectPassRecordFile(const QString &path, QString *why);

} // namespace slew::records
