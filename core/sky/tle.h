// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Two-line element sets: the mean orbital elements NORAD publishes for each
// object, in the fixed-column text format of Spacetrack Report #3. A file
// holds many sets, each two lines with an optional name line before them.
// Reading never gives up on the whole file: a set that cannot be read is
// refused with its line number and the reason, and the rest still loads.

#include <QList>
#include <QString>
#include <QStringView>

namespace slew::sky {

struct Tle {
    QString name;               // the name line, trimmed; empty for a two-line set
    int catalogueNumber = 0;    // NORAD number (Alpha-5 letters are decoded)
    QString designator;         // international designator, e.g. "98067A"
    int epochYear = 0;          // four digits
    double epochDayOfYear = 0;  // 1.0 is 1 January 00:00 UTC
    double meanMotionDot = 0;   // rev/day², as printed (first derivative / 2)
    double meanMotionDdot = 0;  // rev/day³, as printed (second derivative / 6)
    double bstar = 0;           // 1/earth radii
    double inclinationDeg = 0;
    double raanDeg = 0;         // right ascension of the ascending node
    double eccentricity = 0;
    double argPerigeeDeg = 0;
    double meanAnomalyDeg = 0;
    double meanMotionRevPerDay = 0;
    int revolutionNumber = 0;
    QString line1;
    QString line2;

    // Epoch as a Julian date (UTC), split so the fraction keeps its digits.
    double epochJulianDay() const;      // the midnight, x.5
    double epochDayFraction() const;    // 0 <= f < 1
    double epochJulian() const { return epochJulianDay() + epochDayFraction(); }
    QString displayName() const;        // the name, or the catalogue number
};

struct TleRefusal {
    int line = 0;     // 1-based line number of the line at fault
    QString reason;
};

struct TleReadResult {
    QList<Tle> sets;
    QList<TleRefusal> refusals;
};

// The modulo-10 checksum of a line's first 68 columns: digits count their
// value, '-' counts one, everything else nothing.
int tleChecksum(QStringView line);

// One set from its two element lines; the reason on refusal (line is 1 or 2).
// Checksums are always checked for real data; the published verification set
// deliberately carries some wrong ones, so its test may skip them.
bool parseTle(const QString &line1, const QString &line2, Tle *out, TleRefusal *refusal,
              bool checkChecksums = true);

// A whole file or pasted text: two- and three-line sets, in any mix.
TleReadResult readTleText(const QString &text);

// Faster than this is no orbit: a larger mean motion is refused.
inline constexpr double kMostRevolutionsPerDay = 20.0;

// The largest element-set file read or downloaded: CelesTrak's whole active
// catalogue is about 2 MiB.
inline constexpr qint64 kLargestElementFile = 16 * 1024 * 1024;

// One set a satellite: where a file holds a catalogue number twice (two
// group files put together), the newest epoch is kept, in the place of the
// first.
QList<Tle> mergeByCatalogueNumber(const QList<Tle> &sets);

// An element-set file a user named (--tle): only a regular file of at most
// kLargestElementFile, read without blocking on a device or a FIFO, its sets
// merged by catalogue number.
struct TleFile {
    QList<Tle> sets;
    QList<TleRefusal> refusals;
    int duplicates = 0; // sets dropped for an older copy of the same satellite
    QString error;      // the file could not be read at all
};
TleFile readTleFile(const QString &path);

// The sets a query names: a catalogue number matches exactly; otherwise a
// case-insensitive prefix of the name. An exact name match wins over prefixes.
QList<const Tle *> findTles(const QList<Tle> &sets, const QString &query);

// Exactly one set for a query, or nothing and *error: "no satellite 'X'" or
// "'NOAA' matches 19 satellites: NOAA 15 (25338), …". Every place a user
// names a satellite (--passes, --where, --track) uses this, so an ambiguous
// name is refused everywhere, naming the matches.
const Tle *findOneTle(const QList<Tle> &sets, const QString &query, QString *error);

} // namespace slew::sky
