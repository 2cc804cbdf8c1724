// SPDX-License-Identifier: GPL-3.0-or-later
#include "tle.h"

#include "input/boundedfile.h"
#include "input/finitenumber.h"
#include "input/logtext.h"

#include <QHash>
#include <QStringList>

#include <cmath>

namespace slew::sky {
namespace {

// Julian date of 1 January, 00:00, of a Gregorian year.
double julianDayOfNewYear(int year)
{
    return 367.0 * year - std::floor(7.0 * year / 4.0) + 31.0 + 1721013.5;
}

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

// The "assumed decimal point" fields: " 12345-3" is 0.12345e-3.
bool readPackedExponent(QStringView text, double *out)
{
    const QString t = text.toString().trimmed();
    if (t.isEmpty()) {
        *out = 0.0;
        return true;
    }
    int split = t.size() - 2;
    if (split < 1 || (t[split] != u'-' && t[split] != u'+'))
        return false;
    QString mantissa = t.left(split);
    double sign = 1.0;
    if (mantissa.startsWith(u'-') || mantissa.startsWith(u'+')) {
        sign = mantissa.startsWith(u'-') ? -1.0 : 1.0;
        mantissa.remove(0, 1);
    }
    bool okMantissa = false, okExponent = false;
    const double m = QString(QStringLiteral("0.") + mantissa.trimmed()).toDouble(&okMantissa);
    const int e = t.mid(split).toInt(&okExponent);
    if (!okMantissa || !okExponent)
        return false;
    *out = sign * m * std::pow(10.0, e);
    return std::isfinite(*out);
}

// Catalogue numbers past 99999 use Alpha-5: a letter (I and O skipped)
// stands for 10..33 in the first column.
bool readCatalogueNumber(QStringView text, int *out)
{
    const QStringView t = text.trimmed();
    if (t.isEmpty())
        return false;
    const QChar first = t[0].toUpper();
    if (first.isLetter()) {
        static const QString letters = QStringLiteral("ABCDEFGHJKLMNPQRSTUVWXYZ");
        const int index = letters.indexOf(first);
        int rest = 0;
        if (index < 0 || !readInt(t.mid(1), &rest))
            return false;
        *out = (10 + index) * 10000 + rest;
        return true;
    }
    return readInt(t, out);
}

bool refuse(TleRefusal *refusal, int line, const QString &reason)
{
    if (refusal) {
        refusal->line = line;
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

} // namespace

double Tle::epochJulianDay() const
{
    return julianDayOfNewYear(epochYear) - 1.0 + std::floor(epochDayOfYear);
}

double Tle::epochDayFraction() const
{
    return epochDayOfYear - std::floor(epochDayOfYear);
}

QString Tle::displayName() const
{
    return name.isEmpty() ? QString::number(catalogueNumber) : name;
}

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

bool parseTle(const QString &line1In, const QString &line2In, Tle *out, TleRefusal *refusal, bool checkChecksums)
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

    Tle t;
    int number2 = 0, twoDigitYear = 0;
    if (!readCatalogueNumber(columns(line1, 3, 7), &t.catalogueNumber))
        return refuse(refusal, 1, QStringLiteral("catalogue number is not a number"));
    if (!readCatalogueNumber(columns(line2, 3, 7), &number2) || number2 != t.catalogueNumber)
        return refuse(refusal, 2, QStringLiteral("catalogue number differs from line 1's"));
    t.designator = columns(line1, 10, 17).trimmed().toString();
    if (!readInt(columns(line1, 19, 20), &twoDigitYear) || !readDouble(columns(line1, 21, 32), &t.epochDayOfYear))
        return refuse(refusal, 1, QStringLiteral("epoch is not a number"));
    // Spacetrack's convention: two-digit years 57..99 are 1957..1999.
    t.epochYear = twoDigitYear < 57 ? 2000 + twoDigitYear : 1900 + twoDigitYear;
    if (t.epochDayOfYear < 1.0 || t.epochDayOfYear >= 367.0)
        return refuse(refusal, 1, QStringLiteral("epoch day %1 is outside 1..366").arg(t.epochDayOfYear));
    if (!readDouble(columns(line1, 34, 43), &t.meanMotionDot))
        return refuse(refusal, 1, QStringLiteral("first derivative of mean motion is not a number"));
    if (!readPackedExponent(columns(line1, 45, 52), &t.meanMotionDdot))
        return refuse(refusal, 1, QStringLiteral("second derivative of mean motion is not a number"));
    if (!readPackedExponent(columns(line1, 54, 61), &t.bstar))
        return refuse(refusal, 1, QStringLiteral("B* drag term is not a number"));

    if (!readDouble(columns(line2, 9, 16), &t.inclinationDeg) || t.inclinationDeg < 0 || t.inclinationDeg > 180)
        return refuse(refusal, 2, QStringLiteral("inclination must be 0..180 degrees"));
    if (!readDouble(columns(line2, 18, 25), &t.raanDeg) || t.raanDeg < 0 || t.raanDeg > 360)
        return refuse(refusal, 2, QStringLiteral("right ascension of the node must be 0..360 degrees"));
    const QString eccentricityDigits = columns(line2, 27, 33).trimmed().toString();
    bool eccentricityOk = !eccentricityDigits.isEmpty();
    for (QChar c : eccentricityDigits)
        eccentricityOk = eccentricityOk && c.isDigit();
    if (!eccentricityOk)
        return refuse(refusal, 2, QStringLiteral("eccentricity must be digits (an assumed leading decimal point)"));
    t.eccentricity = QString(QStringLiteral("0.") + eccentricityDigits).toDouble();
    if (!readDouble(columns(line2, 35, 42), &t.argPerigeeDeg) || t.argPerigeeDeg < 0 || t.argPerigeeDeg > 360)
        return refuse(refusal, 2, QStringLiteral("argument of perigee must be 0..360 degrees"));
    if (!readDouble(columns(line2, 44, 51), &t.meanAnomalyDeg) || t.meanAnomalyDeg < 0 || t.meanAnomalyDeg > 360)
        return refuse(refusal, 2, QStringLiteral("mean anomaly must be 0..360 degrees"));
    // Nothing in orbit goes round faster than about 17 times a day; a larger
    // figure is a corrupt set, and SGP4 would follow it off any sensible path.
    if (!readDouble(columns(line2, 53, 63), &t.meanMotionRevPerDay) || t.meanMotionRevPerDay <= 0
        || t.meanMotionRevPerDay > kMostRevolutionsPerDay)
        return refuse(refusal, 2, QStringLiteral("mean motion must be a number of revolutions a day above 0 and at "
                                                 "most %1").arg(kMostRevolutionsPerDay));
    if (!readInt(columns(line2, 64, 68), &t.revolutionNumber))
        return refuse(refusal, 2, QStringLiteral("revolution number is not a number"));

    t.line1 = line1.left(69);
    t.line2 = line2.left(69);
    *out = t;
    return true;
}

TleReadResult readTleText(const QString &text)
{
    TleReadResult result;
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
                result.refusals.append({where, QStringLiteral("line 1 is not followed by a line 2")});
                pendingName.clear();
                continue;
            }
            Tle tle;
            TleRefusal refusal;
            if (parseTle(line, next, &tle, &refusal)) {
                tle.name = pendingName;
                result.sets.append(tle);
            } else {
                refusal.line = lineNumber + refusal.line - 1;
                result.refusals.append(refusal);
            }
            pendingName.clear();
            ++i;
            continue;
        }
        if (line.startsWith(QStringLiteral("2 "))) {
            result.refusals.append({lineNumber, QStringLiteral("line 2 without a line 1 before it")});
            pendingName.clear();
            continue;
        }
        if (!pendingName.isEmpty())
            result.refusals.append({pendingNameLine, QStringLiteral("name line without element lines after it")});
        // CelesTrak's three-line files sometimes prefix the name with "0 ".
        pendingName = line.startsWith(QStringLiteral("0 ")) ? line.mid(2).trimmed() : line;
        pendingNameLine = lineNumber;
    }
    if (!pendingName.isEmpty())
        result.refusals.append({pendingNameLine, QStringLiteral("name line without element lines after it")});
    return result;
}

QList<const Tle *> findTles(const QList<Tle> &sets, const QString &query)
{
    QList<const Tle *> found;
    const QString q = query.trimmed();
    bool isNumber = false;
    const int number = q.toInt(&isNumber);
    if (isNumber) {
        for (const Tle &t : sets)
            if (t.catalogueNumber == number)
                found.append(&t);
        if (!found.isEmpty())
            return found;
    }
    for (const Tle &t : sets)
        if (t.name.compare(q, Qt::CaseInsensitive) == 0)
            found.append(&t);
    if (!found.isEmpty())
        return found;
    for (const Tle &t : sets)
        if (t.name.startsWith(q, Qt::CaseInsensitive))
            found.append(&t);
    return found;
}

QList<Tle> mergeByCatalogueNumber(const QList<Tle> &sets)
{
    QList<Tle> merged;
    QHash<int, qsizetype> where;
    for (const Tle &t : sets) {
        const auto it = where.constFind(t.catalogueNumber);
        if (it == where.cend()) {
            where.insert(t.catalogueNumber, merged.size());
            merged.append(t);
        } else if (merged[*it].epochJulian() < t.epochJulian()) {
            merged[*it] = t;
        }
    }
    return merged;
}

const Tle *findOneTle(const QList<Tle> &sets, const QString &query, QString *error)
{
    const QList<const Tle *> found = findTles(sets, query);
    const QString shown = input::loggableText(query.trimmed(), 60);
    if (found.isEmpty()) {
        *error = QStringLiteral("no satellite '%1'").arg(shown);
        return nullptr;
    }
    if (found.size() > 1) {
        QStringList names;
        for (const Tle *t : found.mid(0, 8))
            names << QStringLiteral("%1 (%2)").arg(input::loggableText(t->displayName(), 40)).arg(t->catalogueNumber);
        *error = QStringLiteral("'%1' matches %2 satellites: %3%4; give the catalogue number or more of the name")
                     .arg(shown)
                     .arg(found.size())
                     .arg(names.join(QStringLiteral(", ")), found.size() > 8 ? QStringLiteral(", …") : QString());
        return nullptr;
    }
    return found.first();
}

TleFile readTleFile(const QString &path)
{
    TleFile file;
    const input::BoundedRead read = input::readBoundedFile(path, kLargestElementFile);
    if (!read.ok()) {
        file.error = read.error;
        return file;
    }
    TleReadResult text = readTleText(QString::fromUtf8(read.bytes));
    file.refusals = text.refusals;
    file.sets = mergeByCatalogueNumber(text.sets);
    file.duplicates = int(text.sets.size() - file.sets.size());
    return file;
}

} // namespace slew::sky
