// SPDX-License-Identifier: GPL-3.0-or-later
#include "elementset.h"

#include "satellitenames.h"

#include "input/logtext.h"

#include <QHash>
#include <QStringList>

namespace slew::sky {
namespace {

// Alpha-5's letters: I and O are left out, as they read as 1 and 0.
constexpr char kAlpha5Letters[] = "ABCDEFGHJKLMNPQRSTUVWXYZ";
constexpr int kLargestAlpha5 = 339999;

bool allDigits(QStringView text)
{
    if (text.isEmpty())
        return false;
    for (const QChar c : text)
        if (c < u'0' || c > u'9')
            return false;
    return true;
}

} // namespace

QString ElementSet::displayName() const
{
    return name.isEmpty() ? QString::number(catalogueNumber) : name;
}

QString ElementSetRefusal::place() const
{
    return line > 0 ? QString::number(line) : QStringLiteral("entry %1").arg(entry);
}

QString ElementSetRefusal::where() const
{
    return line > 0 ? QStringLiteral("line %1").arg(line) : QStringLiteral("entry %1").arg(entry);
}

std::optional<int> catalogueNumberFromAlpha5(QStringView text)
{
    const QStringView t = text.trimmed();
    if (allDigits(t)) {
        if (t.size() > 9)
            return std::nullopt;
        return t.toInt();
    }
    if (t.size() != 5 || !allDigits(t.mid(1)))
        return std::nullopt;
    const char first = char(t[0].toUpper().unicode());
    for (int i = 0; kAlpha5Letters[i]; ++i)
        if (kAlpha5Letters[i] == first)
            return (10 + i) * 10000 + t.mid(1).toInt();
    return std::nullopt;
}

std::optional<QString> alpha5FromCatalogueNumber(int number)
{
    if (number < 0 || number > kLargestAlpha5)
        return std::nullopt;
    if (number <= 99999)
        return QStringLiteral("%1").arg(number, 5, 10, QLatin1Char('0'));
    return QLatin1Char(kAlpha5Letters[number / 10000 - 10]) + QStringLiteral("%1").arg(number % 10000, 4, 10, QLatin1Char('0'));
}

QList<ElementSet> mergeByCatalogueNumber(const QList<ElementSet> &sets)
{
    QList<ElementSet> merged;
    merged.reserve(sets.size());
    QHash<int, qsizetype> where;
    where.reserve(sets.size());
    for (const ElementSet &s : sets) {
        const auto it = where.constFind(s.catalogueNumber);
        if (it == where.cend()) {
            where.insert(s.catalogueNumber, merged.size());
            merged.append(s);
        } else if (merged[*it].epochJulian() < s.epochJulian()) {
            merged[*it] = s;
        }
    }
    return merged;
}

QList<const ElementSet *> findSatellites(const QList<ElementSet> &sets, const QString &query)
{
    // The sets one rule takes; the search stops at the first rule that
    // takes any.
    const auto every = [&sets](const auto &takes) {
        QList<const ElementSet *> found;
        for (const ElementSet &s : sets)
            if (takes(s))
                found.append(&s);
        return found;
    };
    const auto numbered = [](std::optional<int> number) {
        return [number](const ElementSet &s) { return number && s.catalogueNumber == *number; };
    };
    const QString q = query.trimmed();
    if (QList<const ElementSet *> found = every(numbered(catalogueNumberFromAlpha5(q))); !found.isEmpty())
        return found;
    // By the names operators use (satellitenames.h), most telling first:
    // the whole name or a designation in it, a name from the table the set lacks,
    // the start of the name, then any part of it.
    const QString key = satelliteNameKey(q);
    if (key.isEmpty())
        return {};
    if (QList<const ElementSet *> found = every([&key](const ElementSet &s) { return satelliteNameKeys(s.name).contains(key); });
        !found.isEmpty())
        return found;
    if (QList<const ElementSet *> found = every(numbered(satelliteNames().catalogueNumber(key))); !found.isEmpty())
        return found;
    if (QList<const ElementSet *> found = every([&key](const ElementSet &s) { return satelliteNameKey(s.name).startsWith(key); });
        !found.isEmpty())
        return found;
    return every([&key](const ElementSet &s) { return satelliteNameKey(s.name).contains(key); });
}

const ElementSet *findOneSatellite(const QList<ElementSet> &sets, const QString &query, QString *error)
{
    const QList<const ElementSet *> found = findSatellites(sets, query);
    const QString shown = input::loggableText(query.trimmed(), 60);
    if (found.isEmpty()) {
        *error = QStringLiteral("no satellite '%1'").arg(shown);
        return nullptr;
    }
    if (found.size() > 1) {
        QStringList names;
        for (const ElementSet *s : found.mid(0, 8))
            names << QStringLiteral("%1 (%2)").arg(input::loggableText(s->displayName(), 40)).arg(s->catalogueNumber);
        *error = QStringLiteral("'%1' matches %2 satellites: %3%4; give the catalogue number or more of the name")
                     .arg(shown)
                     .arg(found.size())
                     .arg(names.join(QStringLiteral(", ")), found.size() > 8 ? QStringLiteral(", …") : QString());
        return nullptr;
    }
    return found.first();
}

} // namespace slew::sky
