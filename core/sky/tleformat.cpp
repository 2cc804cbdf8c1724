// SPDX-License-Identifier: GPL-3.0-or-later
#include "tleformat.h"

#include "civildate.h"
#include "gpfields.h"

#include "input/finitenumber.h"

#include <QStringList>

#include <cmath>

namespace slew::sky {
namespace {

// Columns are 1-based and inclusive, as Spacetrack Report #3 prints them.
QStringView columns(QStringView line, int first, int last)
{
    return line.mid(first - 1, last - first + 1);
}

// Finite numbers only (core/input): "nan" and "inf" read as numbers to Qt,
// and a NaN in any field passes every range check after it.
bool readDouble(QStringView text, double *out)
{
    const std::optional<double> value = input::finiteNumber(text);
    if (!value)
        return false;
    *out = *value;
    return true;
}

bool readInt(QStringView text, int *out)
{
    bool ok = false;
    const QStringView t = text.trimmed();
    *out = t.isEmpty() ? 0 : t.toInt(&ok);
    return t.isEmpty() || ok;
}

// The "assumed decimal point" fields: " 12345-3" is 0.12345e-3. Read as the
// text "0.12345e-3", so the value is the double nearest to it, as for the
// same number written out in an OMM ("1.2345e-04").
bool readPackedExponent(QStringView text, double *out)
{
    const QStringView t = text.trimmed();
    if (t.isEmpty()) {
        *out = 0.0;
        return true;
    }
    const qsizetype split = t.size() - 2;
    if (split < 1 || (t[split] != u'-' && t[split] != u'+') || !t[split + 1].isDigit())
        return false;
    QStringView mantissa = t.left(split);
    QString number;
    if (mantissa.startsWith(u'-') || mantissa.startsWith(u'+')) {
        number += mantissa[0];
        mantissa = mantissa.mid(1);
    }
    mantissa = mantissa.trimmed();
    if (mantissa.isEmpty())
        return false;
    for (const QChar c : mantissa)
        if (!c.isDigit())
            return false;
    number += QStringLiteral("0.") + mantissa.toString() + u'e' + t.mid(split).toString();
    return readDouble(number, out);
}

// "ddd.dddddddd": the day of the year and the fraction of the day, the
// fraction as its digits over a power of ten (one division, so it is the
// double nearest to the decimal the line prints).
bool readEpochDay(QStringView text, int *day, double *fraction)
{
    const QStringView t = text.trimmed();
    const qsizetype dot = t.indexOf(u'.');
    const QStringView whole = dot < 0 ? t : t.left(dot);
    const QStringView digits = dot < 0 ? QStringView() : t.mid(dot + 1);
    if (whole.isEmpty() || digits.size() > 15)
        return false;
    long long d = 0, f = 0, scale = 1;
    for (const QChar c : whole) {
        if (!c.isDigit())
            return false;
        d = d * 10 + c.digitValue();
    }
    for (const QChar c : digits) {
        if (!c.isDigit())
            return false;
        f = f * 10 + c.digitValue();
        scale *= 10;
    }
    if (d > 366)
        return false;
    *day = int(d);
    *fraction = double(f) / double(scale);
    return true;
}

bool refuse(ElementSetRefusal *refusal, int line, const QString &reason)
{
    if (refusal) {
        refusal->line = line;
        refusal->entry = 0;
        refusal->reason = reason;
    }
    return false;
}

bool lineHasRightShape(const QString &line, QChar number)
{
    return line.size() >= 68 && line[0] == number && line[1] == u' ';
}

bool checksumMatches(const QString &line)
{
    return line.size() >= 69 && line[68].isDigit() && line[68].digitValue() == tleChecksum(line);
}

// Which of the two lines holds a field.
int lineOf(GpField field)
{
    switch (field) {
    case GpField::Inclination:
    case GpField::RaOfAscNode:
    case GpField::Eccentricity:
    case GpField::ArgOfPericenter:
    case GpField::MeanAnomaly:
    case GpField::MeanMotion:
    case GpField::RevAtEpoch:
        return 2;
    default:
        return 1;
    }
}

// A TLE's designator ("98067A", columns 10-17) as OMM writes it
// ("1998-067A"); kept as it is when it has another shape.
QString designatorFromTle(QStringView text)
{
    const QStringView t = text.trimmed();
    if (t.size() < 6)
        return t.toString();
    for (int i = 0; i < 5; ++i)
        if (!t[i].isDigit())
            return t.toString();
    const int twoDigitYear = t.left(2).toInt();
    const int year = twoDigitYear < 57 ? 2000 + twoDigitYear : 1900 + twoDigitYear;
    return QStringLiteral("%1-%2").arg(year).arg(t.mid(2));
}

// The other way: "1998-067A" -> "98067A", padded to the eight columns.
QString designatorForTle(const QString &designator)
{
    const QString d = designator.trimmed();
    if (d.size() >= 9 && d.size() <= 12 && d[4] == u'-') {
        bool ok = true;
        for (int i : {0, 1, 2, 3, 5, 6, 7})
            ok = ok && d[i].isDigit();
        if (ok)
            return (d.mid(2, 2) + d.mid(5)).leftJustified(8, u' ', true);
    }
    return QString(8, u' ');
}

// " .00002182" / "-.00002182": columns 34-43.
std::optional<QString> derivativeColumns(double value)
{
    const QString digits = QString::number(std::fabs(value), 'f', 8);
    if (!digits.startsWith(QStringLiteral("0.")))
        return std::nullopt;
    return (value < 0 && digits != QStringLiteral("0.00000000") ? QStringLiteral("-") : QStringLiteral(" "))
           + digits.mid(1);
}

// " 12345-3" for 0.12345e-3: eight columns, the point assumed before the
// five digits.
std::optional<QString> packedExponentColumns(double value)
{
    if (value == 0.0 || std::fabs(value) < 1e-10)
        return QStringLiteral(" 00000-0");
    int exponent = int(std::floor(std::log10(std::fabs(value)))) + 1;
    long long mantissa = std::llround(std::fabs(value) / std::pow(10.0, exponent) * 1e5);
    if (mantissa >= 100000) {
        mantissa /= 10;
        ++exponent;
    }
    if (exponent > 9 || exponent < -9)
        return std::nullopt;
    return QString(value < 0 ? u'-' : u' ') + QStringLiteral("%1").arg(mantissa, 5, 10, QLatin1Char('0'))
           + (exponent < 0 ? u'-' : u'+') + QString::number(std::abs(exponent));
}

QString withChecksum(const QString &line)
{
    return line + QString::number(tleChecksum(line));
}

} // namespace

int tleChecksum(QStringView line)
{
    int sum = 0;
    for (qsizetype i = 0; i < std::min<qsizetype>(68, line.size()); ++i) {
        if (line[i].isDigit())
            sum += line[i].digitValue();
        else if (line[i] == u'-')
            sum += 1;
    }
    return sum % 10;
}

bool parseTle(const QString &line1In, const QString &line2In, ElementSet *out, ElementSetRefusal *refusal,
              bool checkChecksums)
{
    const QString line1 = line1In.trimmed();
    const QString line2 = line2In.trimmed();
    if (!lineHasRightShape(line1, u'1'))
        return refuse(refusal, 1, QStringLiteral("not a TLE line 1 (it must start \"1 \" and have 69 columns)"));
    if (!lineHasRightShape(line2, u'2'))
        return refuse(refusal, 2, QStringLiteral("not a TLE line 2 (it must start \"2 \" and have 69 columns)"));
    if (checkChecksums && !checksumMatches(line1))
        return refuse(refusal, 1, QStringLiteral("checksum: column 69 says %1, the line sums to %2")
                                      .arg(line1.size() >= 69 ? line1.mid(68, 1) : QStringLiteral("nothing"))
                                      .arg(tleChecksum(line1)));
    if (checkChecksums && !checksumMatches(line2))
        return refuse(refusal, 2, QStringLiteral("checksum: column 69 says %1, the line sums to %2")
                                      .arg(line2.mid(68, 1))
                                      .arg(tleChecksum(line2)));

    ElementSet s;
    const std::optional<int> number1 = catalogueNumberFromAlpha5(columns(line1, 3, 7));
    if (!number1)
        return refuse(refusal, 1, QStringLiteral("catalogue number is not a number"));
    if (catalogueNumberFromAlpha5(columns(line2, 3, 7)) != number1)
        return refuse(refusal, 2, QStringLiteral("catalogue number differs from line 1's"));
    s.catalogueNumber = *number1;
    if (line1[7].isLetter())
        s.classification = char(line1[7].toUpper().unicode());
    s.designator = designatorFromTle(columns(line1, 10, 17));
    int twoDigitYear = 0, day = 0, ephemerisType = 0;
    if (!readInt(columns(line1, 19, 20), &twoDigitYear) || !readEpochDay(columns(line1, 21, 32), &day, &s.epochDayFraction))
        return refuse(refusal, 1, QStringLiteral("epoch is not a number"));
    // Spacetrack's convention: two-digit years 57..99 are 1957..1999.
    const int year = twoDigitYear < 57 ? 2000 + twoDigitYear : 1900 + twoDigitYear;
    if (day < 1 || day > (isLeapYear(year) ? 366 : 365))
        return refuse(refusal, 1, QStringLiteral("epoch day %1 is outside 1..%2").arg(day).arg(isLeapYear(year) ? 366 : 365));
    s.epochJulianDay = julianDayOfYearDay(year, day);
    if (!readDouble(columns(line1, 34, 43), &s.meanMotionDot))
        return refuse(refusal, 1, QStringLiteral("first derivative of mean motion is not a number"));
    if (!readPackedExponent(columns(line1, 45, 52), &s.meanMotionDdot))
        return refuse(refusal, 1, QStringLiteral("second derivative of mean motion is not a number"));
    if (!readPackedExponent(columns(line1, 54, 61), &s.bstar))
        return refuse(refusal, 1, QStringLiteral("B* drag term is not a number"));
    if (!readInt(columns(line1, 63, 63), &ephemerisType) || !readInt(columns(line1, 65, 68), &s.elementSetNumber))
        return refuse(refusal, 1, QStringLiteral("ephemeris type or element set number is not a number"));
    if (ephemerisType == 4)
        return refuse(refusal, 1, QStringLiteral("ephemeris type 4 is an SGP4-XP element set, which SGP4 cannot propagate"));

    if (!readDouble(columns(line2, 9, 16), &s.inclinationDeg))
        return refuse(refusal, 2, QStringLiteral("inclination is not a number"));
    if (!readDouble(columns(line2, 18, 25), &s.raanDeg))
        return refuse(refusal, 2, QStringLiteral("right ascension of the node is not a number"));
    const QStringView eccentricityDigits = columns(line2, 27, 33).trimmed();
    bool eccentricityOk = !eccentricityDigits.isEmpty();
    for (QChar c : eccentricityDigits)
        eccentricityOk = eccentricityOk && c.isDigit();
    if (!eccentricityOk)
        return refuse(refusal, 2, QStringLiteral("eccentricity must be digits (an assumed leading decimal point)"));
    s.eccentricity = (QStringLiteral("0.") + eccentricityDigits.toString()).toDouble();
    if (!readDouble(columns(line2, 35, 42), &s.argPerigeeDeg))
        return refuse(refusal, 2, QStringLiteral("argument of perigee is not a number"));
    if (!readDouble(columns(line2, 44, 51), &s.meanAnomalyDeg))
        return refuse(refusal, 2, QStringLiteral("mean anomaly is not a number"));
    if (!readDouble(columns(line2, 53, 63), &s.meanMotionRevPerDay))
        return refuse(refusal, 2, QStringLiteral("mean motion is not a number"));
    if (!readInt(columns(line2, 64, 68), &s.revolutionNumber))
        return refuse(refusal, 2, QStringLiteral("revolution number is not a number"));
    // The ranges every form shares (gpfields.h): nothing in orbit goes round
    // faster than about 17 times a day, and a larger figure is a corrupt
    // set that SGP4 would follow off any sensible path.
    if (const std::optional<GpFieldProblem> problem = fieldOutOfRange(s))
        return refuse(refusal, lineOf(problem->field), problem->reason);
    *out = s;
    return true;
}

ElementSetRead readTleText(const QString &text)
{
    ElementSetRead result;
    const QStringList lines = text.split(u'\n');
    QString pendingName;
    int pendingNameLine = 0;
    for (int i = 0; i < lines.size(); ++i) {
        const QString line = lines[i].trimmed();
        const int lineNumber = i + 1;
        if (line.isEmpty() || line.startsWith(u'#'))
            continue;
        if (line.startsWith(QStringLiteral("1 "))) {
            const QString next = i + 1 < lines.size() ? lines[i + 1].trimmed() : QString();
            if (!next.startsWith(QStringLiteral("2 "))) {
                // The line where the line 2 should be; the line 1 itself when
                // the file ends there (a download cut short).
                const int where = i + 1 < lines.size() ? lineNumber + 1 : lineNumber;
                result.refusals.append({where, 0, QStringLiteral("line 1 is not followed by a line 2")});
                pendingName.clear();
                continue;
            }
            ElementSet set;
            ElementSetRefusal refusal;
            if (parseTle(line, next, &set, &refusal)) {
                set.name = pendingName;
                result.sets.append(set);
            } else {
                refusal.line = lineNumber + refusal.line - 1;
                result.refusals.append(refusal);
            }
            pendingName.clear();
            ++i;
            continue;
        }
        if (line.startsWith(QStringLiteral("2 "))) {
            result.refusals.append({lineNumber, 0, QStringLiteral("line 2 without a line 1 before it")});
            pendingName.clear();
            continue;
        }
        if (!pendingName.isEmpty())
            result.refusals.append({pendingNameLine, 0, QStringLiteral("name line without element lines after it")});
        // CelesTrak's three-line files sometimes prefix the name with "0 ".
        pendingName = line.startsWith(QStringLiteral("0 ")) ? line.mid(2).trimmed() : line;
        pendingNameLine = lineNumber;
    }
    if (!pendingName.isEmpty())
        result.refusals.append({pendingNameLine, 0, QStringLiteral("name line without element lines after it")});
    return result;
}

std::optional<QString> tleText(const ElementSet &s, QString *why)
{
    const std::optional<QString> number = alpha5FromCatalogueNumber(s.catalogueNumber);
    if (!number) {
        *why = QStringLiteral("catalogue number %1 is above 339999, the most a TLE can carry (Alpha-5)")
                   .arg(s.catalogueNumber);
        return std::nullopt;
    }
    // The epoch's day, its fraction to eight places (a whole number of
    // 864 µs), carried into the next day when it rounds up to one.
    long long fraction = std::llround(s.epochDayFraction * 1e8);
    double julianDay = s.epochJulianDay;
    if (fraction >= 100000000LL) {
        fraction -= 100000000LL;
        julianDay += 1.0;
    }
    const CivilDate date = civilDateOfJulian(julianDay);
    if (date.year < 1957 || date.year > 2056) {
        *why = QStringLiteral("epoch year %1 is outside the TLE's 1957..2056").arg(date.year);
        return std::nullopt;
    }
    const std::optional<QString> dot = derivativeColumns(s.meanMotionDot);
    const std::optional<QString> ddot = packedExponentColumns(s.meanMotionDdot);
    const std::optional<QString> bstar = packedExponentColumns(s.bstar);
    if (!dot || !ddot || !bstar) {
        *why = QStringLiteral("a drag term is wider than its TLE column");
        return std::nullopt;
    }
    const auto angle = [](double degrees) { return QStringLiteral("%1").arg(degrees, 8, 'f', 4); };
    const QString eccentricity = QStringLiteral("%1").arg(std::llround(s.eccentricity * 1e7), 7, 10, QLatin1Char('0'));
    if (eccentricity.size() != 7) {
        *why = QStringLiteral("eccentricity rounds to 1");
        return std::nullopt;
    }
    const QString classification = QString(QChar(s.classification ? s.classification : 'U'));
    const QString line1 = QStringLiteral("1 %1%2 %3 %4%5.%6 %7 %8 %9 0 %10")
                              .arg(*number, classification, designatorForTle(s.designator))
                              .arg(date.year % 100, 2, 10, QLatin1Char('0'))
                              .arg(date.dayOfYear, 3, 10, QLatin1Char('0'))
                              .arg(fraction, 8, 10, QLatin1Char('0'))
                              .arg(*dot, *ddot, *bstar)
                              .arg(s.elementSetNumber % 10000, 4);
    const QString line2 = QStringLiteral("2 %1 %2 %3 %4 %5 %6 %7%8")
                              .arg(*number, angle(s.inclinationDeg), angle(s.raanDeg), eccentricity,
                                   angle(s.argPerigeeDeg), angle(s.meanAnomalyDeg))
                              .arg(s.meanMotionRevPerDay, 11, 'f', 8)
                              .arg(s.revolutionNumber % 100000, 5);
    QString text;
    if (!s.name.isEmpty())
        text += s.name + u'\n';
    return text + withChecksum(line1) + u'\n' + withChecksum(line2) + u'\n';
}

} // namespace slew::sky
