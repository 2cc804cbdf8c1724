// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// An element set: the mean orbital elements NORAD fits to its tracking of
// one object, in the general-perturbations (GP) theory SGP4 propagates. The
// same values come in five forms (elementsetformat.h): the two-line element
// set (TLE) and the four forms of CCSDS's Orbit Mean-Elements Message
// keywords that CelesTrak and Space-Track publish since catalogue numbers
// passed five digits (CSV, OMM XML, JSON, OMM KVN). Whatever the form, a set
// is this one type, and SGP4 starts from its fields, never from text.
//
// Reading never gives up on a whole file: a set that cannot be read is
// refused with its line (or entry) and the reason, and the rest still loads.

#include <QList>
#include <QString>
#include <QStringView>

#include <optional>

namespace slew::sky {

// Catalogue numbers have nine digits since the catalogue passed 99999
// (2026-07-11); TLEs carry five, or six through Alpha-5 (up to 339999).
inline constexpr int kLargestCatalogueNumber = 999999999;

// Faster than this is no orbit: a larger mean motion is refused.
inline constexpr double kMostRevolutionsPerDay = 20.0;

// The largest element-set file read or downloaded: CelesTrak's whole active
// catalogue (some 12,000 objects) is about 2 MB as TLE or CSV, 5 MB as
// JSON, 9 MB as KVN and 15 MB as OMM XML, and the catalogue grows.
inline constexpr qint64 kLargestElementFile = 32 * 1024 * 1024;

struct ElementSet {
    QString name;                 // OBJECT_NAME, or the TLE's name line; may be empty
    int catalogueNumber = 0;      // NORAD_CAT_ID: 1..kLargestCatalogueNumber
    QString designator;           // OBJECT_ID, the international designator as OMM writes it ("1998-067A"); may be empty
    char classification = 'U';    // CLASSIFICATION_TYPE: U, C or S
    int elementSetNumber = 0;     // ELEMENT_SET_NO
    int revolutionNumber = 0;     // REV_AT_EPOCH
    // The epoch, UTC, split so the fraction keeps every digit the source
    // gave (a TLE's eight decimals of a day are a whole number of
    // microseconds, so a TLE and the OMM made from it give the same double).
    double epochJulianDay = 0;    // the epoch's midnight, a Julian date x.5
    double epochDayFraction = 0;  // 0 <= f < 1
    double meanMotionDot = 0;     // MEAN_MOTION_DOT, rev/day², as TLEs print it (half the derivative)
    double meanMotionDdot = 0;    // MEAN_MOTION_DDOT, rev/day³, as printed (a sixth of the derivative)
    double bstar = 0;             // BSTAR, 1/earth radii
    double inclinationDeg = 0;
    double raanDeg = 0;           // RA_OF_ASC_NODE
    double eccentricity = 0;
    double argPerigeeDeg = 0;     // ARG_OF_PERICENTER
    double meanAnomalyDeg = 0;
    double meanMotionRevPerDay = 0;

    double epochJulian() const { return epochJulianDay + epochDayFraction; }
    QString displayName() const;  // the name, or the catalogue number
};

// Where a set that could not be read was, and why.
struct ElementSetRefusal {
    int line = 0;   // 1-based line of the text at fault; 0 where the form has no lines (JSON)
    int entry = 0;  // 1-based entry of a JSON array, when line is 0
    QString reason;

    // "12" or "entry 3": what follows "FILE:" in a message.
    QString place() const;
    // "line 12" or "entry 3": in a sentence.
    QString where() const;
};

struct ElementSetRead {
    QList<ElementSet> sets;
    QList<ElementSetRefusal> refusals;
};

// One set a satellite: where a file holds a catalogue number twice (two
// group files put together, or two forms of one source), the newest epoch
// is kept, in the place of the first.
QList<ElementSet> mergeByCatalogueNumber(const QList<ElementSet> &sets);

// The sets a query names: a catalogue number matches exactly (also written
// in Alpha-5, "A0001"); otherwise, compared as satelliteNameKey (case,
// spaces and hyphens aside), the first of these that finds any: the whole
// name or a designation in parentheses ("ZARYA", "AO-91"), a name from the
// table of satellite names the set lacks ("OSCAR 7", "JAS-2", or the
// operator's own: satellitenames.h), the start of the name, any part of it.
QList<const ElementSet *> findSatellites(const QList<ElementSet> &sets, const QString &query);

// Exactly one set for a query, or nothing and *error: "no satellite 'X'" or
// "'NOAA' matches 19 satellites: NOAA 15 (25338), …". Every place a user
// names a satellite (--passes, --where, --track) uses this, so an ambiguous
// name is refused everywhere, naming the matches.
const ElementSet *findOneSatellite(const QList<ElementSet> &sets, const QString &query, QString *error);

// Alpha-5, the TLE's way past 99999: a letter (I and O skipped) for the
// first two digits, 10..33, then four digits; "A0000" is 100000, "Z9999"
// 339999. Nothing for text that is not a catalogue number in Alpha-5 or
// plain digits.
std::optional<int> catalogueNumberFromAlpha5(QStringView text);
// The five columns a TLE gives the number: digits up to 99999, Alpha-5 up
// to 339999, nothing above.
std::optional<QString> alpha5FromCatalogueNumber(int number);

} // namespace slew::sky
