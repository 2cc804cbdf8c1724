// SPDX-License-Identifier: GPL-3.0-or-later
#include "gpfields.h"

#include "civildate.h"

#include "input/logtext.h"

#include <QLocale>

#include <cmath>

namespace slew::sky {
namespace {

using Kind = GpFieldInfo::Kind;

// Wide enough for every set NORAD publishes, narrow enough that SGP4 never
// meets a value it was not made for. The angles and the mean motion are
// those of a TLE's columns; the drag terms are bounded by what a TLE can
// print (B* up to 0.99999e9, the derivatives well inside ±1000).
constexpr input::NumberRange kAnyDrag{-1e9, 1e9, ""};
constexpr input::NumberRange kDerivative{-1000.0, 1000.0, ""};
constexpr input::NumberRange kNone{0, 0, ""};

// In the order of GpField.
const GpFieldInfo kFields[kGpFieldCount] = {
    {"OBJECT_NAME", "name", Kind::Text, false, kNone},
    {"OBJECT_ID", "international designator", Kind::Text, false, kNone},
    {"EPOCH", "epoch", Kind::Epoch, true, kNone},
    {"MEAN_MOTION", "mean motion", Kind::Number, true, {0.0, kMostRevolutionsPerDay, " rev/day"}},
    {"ECCENTRICITY", "eccentricity", Kind::Number, true, {0.0, 1.0, ""}},
    {"INCLINATION", "inclination", Kind::Number, true, {0.0, 180.0, "°"}},
    {"RA_OF_ASC_NODE", "right ascension of the node", Kind::Number, true, {0.0, 360.0, "°"}},
    {"ARG_OF_PERICENTER", "argument of perigee", Kind::Number, true, {0.0, 360.0, "°"}},
    {"MEAN_ANOMALY", "mean anomaly", Kind::Number, true, {0.0, 360.0, "°"}},
    {"EPHEMERIS_TYPE", "ephemeris type", Kind::Whole, false, {0, 9, ""}},
    {"CLASSIFICATION_TYPE", "classification", Kind::Text, false, kNone},
    {"NORAD_CAT_ID", "catalogue number", Kind::Whole, true, {1, double(kLargestCatalogueNumber), ""}},
    {"ELEMENT_SET_NO", "element set number", Kind::Whole, false, {0, double(kLargestCatalogueNumber), ""}},
    {"REV_AT_EPOCH", "revolution number", Kind::Whole, false, {0, double(kLargestCatalogueNumber), ""}},
    {"BSTAR", "B* drag term", Kind::Number, true, kAnyDrag},
    {"MEAN_MOTION_DOT", "first derivative of mean motion", Kind::Number, false, kDerivative},
    {"MEAN_MOTION_DDOT", "second derivative of mean motion", Kind::Number, false, kDerivative},
    {"MEAN_ELEMENT_THEORY", "mean element theory", Kind::Text, false, kNone},
    {"REF_FRAME", "reference frame", Kind::Text, false, kNone},
    {"TIME_SYSTEM", "time system", Kind::Text, false, kNone},
    {"CENTER_NAME", "centre", Kind::Text, false, kNone},
};

// SGP4-XP, the Space Force's newer theory, publishes with ephemeris type 4:
// its elements propagated by SGP4 go wrong by kilometres.
constexpr int kSgp4XpEphemerisType = 4;

// What the metadata must say when it is given: SGP4's theory, its frame,
// its time scale, the earth.
struct Expected {
    GpField field;
    const char *value;
};
constexpr Expected kExpected[] = {{GpField::MeanElementTheory, "SGP4"},
                                  {GpField::RefFrame, "TEME"},
                                  {GpField::TimeSystem, "UTC"},
                                  {GpField::CenterName, "EARTH"}};

QString quoted(QStringView text)
{
    return QLatin1Char('\'') + input::loggableText(text.trimmed().toString(), 40) + QLatin1Char('\'');
}

bool refuse(ElementSetRefusal *refusal, const GpEntry &entry, const GpValue *value, const QString &reason)
{
    if (refusal) {
        refusal->line = value && value->line > 0 ? value->line : entry.line;
        refusal->entry = entry.entry;
        refusal->reason = reason;
    }
    return false;
}

// Digits only, as many as there are, at most `most` of them.
bool readDigits(QStringView text, qsizetype from, qsizetype count, long long *out)
{
    if (from + count > text.size())
        return false;
    long long value = 0;
    for (qsizetype i = from; i < from + count; ++i) {
        const char16_t c = text[i].unicode();
        if (c < u'0' || c > u'9')
            return false;
        value = value * 10 + (c - u'0');
    }
    *out = value;
    return true;
}

std::optional<double> numberOf(const GpValue &v, const GpFieldInfo &info, QString *why)
{
    if (v.kind == GpValue::Kind::Number) {
        if (!input::checkNumber(v.number, info.range, why))
            return std::nullopt;
        return v.number;
    }
    return input::numberIn(v.text, info.range, why);
}

std::optional<int> wholeOf(const GpValue &v, const GpFieldInfo &info, QString *why)
{
    if (v.kind == GpValue::Kind::Number) {
        if (!input::checkNumber(v.number, info.range, why))
            return std::nullopt;
        if (v.number != std::floor(v.number)) {
            *why = QStringLiteral("%1 is not a whole number").arg(v.number);
            return std::nullopt;
        }
        return int(v.number);
    }
    return input::wholeNumberIn(v.text, int(info.range.min), int(info.range.max), why);
}

// Where a number field goes in the set.
double *numberField(ElementSet &s, GpField field)
{
    switch (field) {
    case GpField::MeanMotion: return &s.meanMotionRevPerDay;
    case GpField::Eccentricity: return &s.eccentricity;
    case GpField::Inclination: return &s.inclinationDeg;
    case GpField::RaOfAscNode: return &s.raanDeg;
    case GpField::ArgOfPericenter: return &s.argPerigeeDeg;
    case GpField::MeanAnomaly: return &s.meanAnomalyDeg;
    case GpField::Bstar: return &s.bstar;
    case GpField::MeanMotionDot: return &s.meanMotionDot;
    case GpField::MeanMotionDdot: return &s.meanMotionDdot;
    default: return nullptr;
    }
}

// Where a whole-number field goes; the ephemeris type is only checked.
int *wholeField(ElementSet &s, int &ephemerisType, GpField field)
{
    switch (field) {
    case GpField::EphemerisType: return &ephemerisType;
    case GpField::NoradCatId: return &s.catalogueNumber;
    case GpField::ElementSetNo: return &s.elementSetNumber;
    case GpField::RevAtEpoch: return &s.revolutionNumber;
    default: return nullptr;
    }
}

} // namespace

const GpFieldInfo &gpFieldInfo(GpField field)
{
    return kFields[int(field)];
}

std::optional<GpField> gpFieldOfKeyword(QStringView keyword)
{
    for (int i = 0; i < kGpFieldCount; ++i)
        if (keyword == QLatin1StringView(kFields[i].keyword))
            return GpField(i);
    return std::nullopt;
}

std::optional<GpField> gpFieldOfKeyword(QLatin1StringView keyword)
{
    for (int i = 0; i < kGpFieldCount; ++i)
        if (keyword == QLatin1StringView(kFields[i].keyword))
            return GpField(i);
    return std::nullopt;
}

void GpEntry::setText(GpField field, QStringView text, int atLine)
{
    GpValue &v = values[int(field)];
    v.kind = GpValue::Kind::Text;
    v.text = text;
    v.line = atLine;
}

void GpEntry::setNumber(GpField field, double number)
{
    GpValue &v = values[int(field)];
    v.kind = GpValue::Kind::Number;
    v.number = number;
}

std::optional<EpochParts> epochFromText(QStringView text)
{
    QStringView t = text.trimmed();
    if (t.endsWith(u'Z') || t.endsWith(u'z'))
        t.chop(1);
    long long year = 0, month = 0, day = 0, dayOfYear = 0, hour = 0, minute = 0, second = 0;
    if (!readDigits(t, 0, 4, &year) || t.size() < 5 || t[4] != u'-')
        return std::nullopt;
    qsizetype at = 5;
    if (readDigits(t, 5, 2, &month) && t.size() > 7 && t[7] == u'-') {
        if (!readDigits(t, 8, 2, &day) || month < 1 || month > 12 || day < 1 || day > daysInMonth(int(year), int(month)))
            return std::nullopt;
        at = 10;
    } else {
        if (!readDigits(t, 5, 3, &dayOfYear) || dayOfYear < 1 || dayOfYear > (isLeapYear(int(year)) ? 366 : 365))
            return std::nullopt;
        at = 8;
    }
    if (t.size() < at + 9 || t[at] != u'T' || !readDigits(t, at + 1, 2, &hour) || t[at + 3] != u':'
        || !readDigits(t, at + 4, 2, &minute) || t[at + 6] != u':' || !readDigits(t, at + 7, 2, &second))
        return std::nullopt;
    if (year < 1957 || year > 2999 || hour > 23 || minute > 59 || second > 59)
        return std::nullopt;
    at += 9;
    // The fraction of the second, to the nanosecond; digits past the ninth
    // are below anything an element set means.
    long long nanoseconds = 0;
    if (at < t.size()) {
        if (t[at] != u'.' || at + 1 >= t.size())
            return std::nullopt;
        long long scale = 100000000;
        for (qsizetype i = at + 1; i < t.size(); ++i) {
            const char16_t c = t[i].unicode();
            if (c < u'0' || c > u'9')
                return std::nullopt;
            nanoseconds += (c - u'0') * scale;
            scale /= 10;
        }
    }
    EpochParts parts;
    parts.julianDay = dayOfYear > 0 ? julianDayOfYearDay(int(year), int(dayOfYear))
                                    : julianDayOfDate(int(year), int(month), int(day));
    // Both whole numbers of nanoseconds, exact in a double: one division,
    // so the same instant written as a TLE's day fraction gives the same bits.
    const long long ofDay = ((hour * 60 + minute) * 60 + second) * 1000000000LL + nanoseconds;
    parts.dayFraction = double(ofDay) / 86400e9;
    return parts;
}

QString epochText(const ElementSet &set)
{
    // The nanoseconds epochFromText() divided by the day's, recovered
    // exactly (the product is within a fiftieth of a whole number).
    constexpr long long kNanosecondsPerDay = 86400000000000LL;
    long long nanoseconds = std::llround(set.epochDayFraction * double(kNanosecondsPerDay));
    double julianDay = set.epochJulianDay;
    if (nanoseconds >= kNanosecondsPerDay) {
        nanoseconds -= kNanosecondsPerDay;
        julianDay += 1.0;
    }
    const CivilDate date = civilDateOfJulian(julianDay);
    const long long seconds = nanoseconds / 1000000000;
    // Microseconds, as CelesTrak writes; nine places where they are needed
    // to read back the same instant.
    const long long ofSecond = nanoseconds % 1000000000;
    const QString fraction = ofSecond % 1000 == 0 ? QStringLiteral("%1").arg(ofSecond / 1000, 6, 10, QLatin1Char('0'))
                                                  : QStringLiteral("%1").arg(ofSecond, 9, 10, QLatin1Char('0'));
    return QStringLiteral("%1-%2-%3T%4:%5:%6.%7")
        .arg(date.year, 4, 10, QLatin1Char('0'))
        .arg(date.month, 2, 10, QLatin1Char('0'))
        .arg(date.day, 2, 10, QLatin1Char('0'))
        .arg(seconds / 3600, 2, 10, QLatin1Char('0'))
        .arg(seconds / 60 % 60, 2, 10, QLatin1Char('0'))
        .arg(seconds % 60, 2, 10, QLatin1Char('0'))
        .arg(fraction);
}

GpValueText gpValueText(const ElementSet &s, GpField field)
{
    const auto number = [](double x) { return GpValueText{QString::number(x, 'g', QLocale::FloatingPointShortest), false}; };
    const auto whole = [](long long n) { return GpValueText{QString::number(n), false}; };
    const auto text = [](const QString &t) { return GpValueText{t, true}; };
    switch (field) {
    case GpField::ObjectName: return text(s.name);
    case GpField::ObjectId: return text(s.designator);
    case GpField::Epoch: return text(epochText(s));
    case GpField::MeanMotion: return number(s.meanMotionRevPerDay);
    case GpField::Eccentricity: return number(s.eccentricity);
    case GpField::Inclination: return number(s.inclinationDeg);
    case GpField::RaOfAscNode: return number(s.raanDeg);
    case GpField::ArgOfPericenter: return number(s.argPerigeeDeg);
    case GpField::MeanAnomaly: return number(s.meanAnomalyDeg);
    case GpField::EphemerisType: return whole(0);
    case GpField::ClassificationType: return text(QString(QChar(s.classification ? s.classification : 'U')));
    case GpField::NoradCatId: return whole(s.catalogueNumber);
    case GpField::ElementSetNo: return whole(s.elementSetNumber);
    case GpField::RevAtEpoch: return whole(s.revolutionNumber);
    case GpField::Bstar: return number(s.bstar);
    case GpField::MeanMotionDot: return number(s.meanMotionDot);
    case GpField::MeanMotionDdot: return number(s.meanMotionDdot);
    case GpField::MeanElementTheory: return text(QStringLiteral("SGP4"));
    case GpField::RefFrame: return text(QStringLiteral("TEME"));
    case GpField::TimeSystem: return text(QStringLiteral("UTC"));
    case GpField::CenterName: return text(QStringLiteral("EARTH"));
    }
    return {};
}

std::optional<GpFieldProblem> fieldOutOfRange(const ElementSet &s)
{
    const struct {
        GpField field;
        double value;
    } numbers[] = {{GpField::NoradCatId, double(s.catalogueNumber)},
                   {GpField::MeanMotion, s.meanMotionRevPerDay},
                   {GpField::Eccentricity, s.eccentricity},
                   {GpField::Inclination, s.inclinationDeg},
                   {GpField::RaOfAscNode, s.raanDeg},
                   {GpField::ArgOfPericenter, s.argPerigeeDeg},
                   {GpField::MeanAnomaly, s.meanAnomalyDeg},
                   {GpField::Bstar, s.bstar},
                   {GpField::MeanMotionDot, s.meanMotionDot},
                   {GpField::MeanMotionDdot, s.meanMotionDdot}};
    for (const auto &n : numbers) {
        const GpFieldInfo &info = gpFieldInfo(n.field);
        QString why;
        if (!input::checkNumber(n.value, info.range, &why))
            return GpFieldProblem{n.field, QStringLiteral("%1 %2").arg(QLatin1String(info.words), why)};
    }
    // A set that goes round no times a day, or an open orbit, is no orbit.
    if (s.meanMotionRevPerDay <= 0)
        return GpFieldProblem{GpField::MeanMotion, QStringLiteral("mean motion must be above 0 revolutions a day")};
    if (s.eccentricity >= 1)
        return GpFieldProblem{GpField::Eccentricity, QStringLiteral("eccentricity must be below 1")};
    return std::nullopt;
}

bool elementSetFromGp(const GpEntry &entry, ElementSet *out, ElementSetRefusal *refusal)
{
    for (int i = 0; i < kGpFieldCount; ++i)
        if (kFields[i].required && entry.values[i].kind == GpValue::Kind::Absent)
            return refuse(refusal, entry, nullptr, QStringLiteral("no %1").arg(QLatin1String(kFields[i].keyword)));
    for (const Expected &e : kExpected) {
        const GpValue &v = entry.values[int(e.field)];
        if (v.kind != GpValue::Kind::Absent && v.text.trimmed().compare(QLatin1StringView(e.value), Qt::CaseInsensitive) != 0)
            return refuse(refusal, entry, &v, QStringLiteral("%1 %2: only %3 element sets are read (SGP4's theory, in "
                                                             "TEME, in UTC, about the earth)")
                                                  .arg(QLatin1String(gpFieldInfo(e.field).keyword), quoted(v.text),
                                                       QLatin1String(e.value)));
    }

    ElementSet set;
    int ephemerisType = 0;
    for (int i = 0; i < kGpFieldCount; ++i) {
        const GpValue &v = entry.values[i];
        const GpFieldInfo &info = kFields[i];
        if (v.kind == GpValue::Kind::Absent)
            continue;
        const QLatin1StringView keyword(info.keyword);
        QString why;
        switch (info.kind) {
        case Kind::Number: {
            const std::optional<double> x = numberOf(v, info, &why);
            if (!x)
                return refuse(refusal, entry, &v, QString(keyword) + u' ' + why);
            *numberField(set, GpField(i)) = *x;
            break;
        }
        case Kind::Whole: {
            const std::optional<int> n = wholeOf(v, info, &why);
            if (!n)
                return refuse(refusal, entry, &v, QString(keyword) + u' ' + why);
            *wholeField(set, ephemerisType, GpField(i)) = *n;
            break;
        }
        case Kind::Epoch: {
            const std::optional<EpochParts> epoch =
                v.kind == GpValue::Kind::Text ? epochFromText(v.text) : std::nullopt;
            if (!epoch)
                return refuse(refusal, entry, &v, QStringLiteral("EPOCH %1 is not a UTC time such as "
                                                                 "2026-07-11T12:34:56.123456")
                                                      .arg(v.kind == GpValue::Kind::Text ? quoted(v.text)
                                                                                          : QString::number(v.number)));
            set.epochJulianDay = epoch->julianDay;
            set.epochDayFraction = epoch->dayFraction;
            break;
        }
        case Kind::Text:
            break;
        }
    }
    if (ephemerisType == kSgp4XpEphemerisType)
        return refuse(refusal, entry, &entry.values[int(GpField::EphemerisType)],
                      QStringLiteral("EPHEMERIS_TYPE 4 is an SGP4-XP element set, which SGP4 cannot propagate"));
    if (const std::optional<GpFieldProblem> problem = fieldOutOfRange(set))
        return refuse(refusal, entry, &entry.values[int(problem->field)],
                      QStringLiteral("%1: %2").arg(QLatin1String(gpFieldInfo(problem->field).keyword), problem->reason));

    const auto text = [&entry](GpField f) {
        const GpValue &v = entry.values[int(f)];
        return v.kind == GpValue::Kind::Text ? v.text.trimmed().toString()
               : v.kind == GpValue::Kind::Number ? QString::number(v.number, 'g', 17)
                                                 : QString();
    };
    set.name = text(GpField::ObjectName);
    set.designator = text(GpField::ObjectId);
    const GpValue &classification = entry.values[int(GpField::ClassificationType)];
    const QStringView letter = classification.text.trimmed().left(1);
    if (classification.kind == GpValue::Kind::Text && !letter.isEmpty() && letter[0].unicode() < 0x80 && letter[0].isLetter())
        set.classification = char(letter[0].toUpper().unicode());
    *out = std::move(set);
    return true;
}

void readGpEntry(const GpEntry &entry, ElementSetRead *read)
{
    ElementSet set;
    ElementSetRefusal refusal;
    if (elementSetFromGp(entry, &set, &refusal))
        read->sets.append(std::move(set));
    else
        read->refusals.append(refusal);
}

} // namespace slew::sky
