// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The fields of an element set as the GP forms name them: the keywords of
// CCSDS's Orbit Mean-Elements Message (CCSDS 502.0-B, "OMM"), which the
// CSV header, the XML tags, the JSON keys and the KVN lines all use. This
// is the one table of what each field is, whether a set needs it, and the
// range its value must lie in; the TLE reader checks the same ranges.
//
// A reader collects one entry's values (text, or a number a JSON parser
// already read) by field, then elementSetFromGp() makes the set or says
// what is wrong, naming the keyword and, where the form has lines, the
// line. Pure code.

#include "elementset.h"

#include "input/finitenumber.h"

#include <QStringView>

#include <array>
#include <optional>

namespace slew::sky {

enum class GpField : int {
    ObjectName,
    ObjectId,
    Epoch,
    MeanMotion,
    Eccentricity,
    Inclination,
    RaOfAscNode,
    ArgOfPericenter,
    MeanAnomaly,
    EphemerisType,
    ClassificationType,
    NoradCatId,
    ElementSetNo,
    RevAtEpoch,
    Bstar,
    MeanMotionDot,
    MeanMotionDdot,
    // Metadata that, when given, must name what SGP4 assumes.
    MeanElementTheory,
    RefFrame,
    TimeSystem,
    CenterName,
};
inline constexpr int kGpFieldCount = int(GpField::CenterName) + 1;

struct GpFieldInfo {
    enum class Kind { Text, Number, Whole, Epoch };
    const char *keyword; // "MEAN_MOTION"
    const char *words;   // "mean motion": how the TLE reader names it
    Kind kind;
    bool required;       // a set cannot be made without it
    input::NumberRange range;
};

const GpFieldInfo &gpFieldInfo(GpField field);
// The field a keyword names (exactly, in capitals, as every form writes
// them); nothing for the keywords Slew does not read.
std::optional<GpField> gpFieldOfKeyword(QStringView keyword);
std::optional<GpField> gpFieldOfKeyword(QLatin1StringView keyword);

// The fields Slew writes, in the order of CelesTrak's CSV header.
inline constexpr std::array<GpField, 17> kGpFieldsWritten = {
    GpField::ObjectName,    GpField::ObjectId,        GpField::Epoch,         GpField::MeanMotion,
    GpField::Eccentricity,  GpField::Inclination,     GpField::RaOfAscNode,   GpField::ArgOfPericenter,
    GpField::MeanAnomaly,   GpField::EphemerisType,   GpField::ClassificationType, GpField::NoradCatId,
    GpField::ElementSetNo,  GpField::RevAtEpoch,      GpField::Bstar,         GpField::MeanMotionDot,
    GpField::MeanMotionDdot};

// One value as a reader found it. A text value views the reader's text,
// which must outlive the entry.
struct GpValue {
    enum class Kind { Absent, Text, Number };
    Kind kind = Kind::Absent;
    QStringView text;
    double number = 0;
    int line = 0; // where the form has lines; 0 otherwise
};

// One entry (a CSV row, an OMM, a JSON object) of values by field.
struct GpEntry {
    std::array<GpValue, kGpFieldCount> values;
    int line = 0;  // where the entry starts (CSV, XML, KVN)
    int entry = 0; // its 1-based place among the entries (JSON)

    void setText(GpField field, QStringView text, int atLine = 0);
    void setNumber(GpField field, double number);
    bool has(GpField field) const { return values[int(field)].kind != GpValue::Kind::Absent; }
};

// The set an entry describes; otherwise false, and *refusal names the
// keyword, the value and what is wrong ("MEAN_MOTION 'nan' is not a finite
// number"), at the value's line (else the entry's line, else its entry).
bool elementSetFromGp(const GpEntry &entry, ElementSet *out, ElementSetRefusal *refusal);
// The same, into a reading: the set among its sets, or the refusal among
// its refusals.
void readGpEntry(const GpEntry &entry, ElementSetRead *read);

// The first field of `set` outside the table's range and why, in the
// table's words ("inclination 190 is outside 0..180°"); nothing when all
// are inside. The TLE reader's check, so a TLE and an OMM accept alike.
struct GpFieldProblem {
    GpField field;
    QString reason;
};
std::optional<GpFieldProblem> fieldOutOfRange(const ElementSet &set);

// An OMM epoch, "2026-07-11T12:34:56.123456" (calendar date) or
// "2026-192T12:34:56.123456" (day of the year), UTC, an optional "Z": the
// Julian date of its midnight and the fraction of the day, exact to the
// nanosecond. Nothing for anything else.
struct EpochParts {
    double julianDay = 0;
    double dayFraction = 0;
};
std::optional<EpochParts> epochFromText(QStringView text);
// The epoch as OMM writes it, to the microsecond ("2026-07-11T12:34:56.123456"),
// or to the nanosecond when the set's epoch has them.
QString epochText(const ElementSet &set);

// A field of a set as the writers put it: numbers in the fewest digits that
// read back to the same double, the epoch to the microsecond, and whether
// it is text (quoted in JSON) or a number.
struct GpValueText {
    QString text;
    bool isText = false;
};
GpValueText gpValueText(const ElementSet &set, GpField field);

} // namespace slew::sky
