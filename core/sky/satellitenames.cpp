// SPDX-License-Identifier: GPL-3.0-or-later
#include "satellitenames.h"

#include "input/boundedfile.h"

#include <QFileInfo>
#include <QStandardPaths>

namespace slew::sky {

namespace {

// An alias file is a few hundred lines; anything this large is not one.
constexpr qint64 kMostUserFileBytes = 1024 * 1024;
// Catalogue numbers are nine digits at most (the GP formats' field).
constexpr int kMostNumberDigits = 9;

struct LoadedNames {
    SatelliteNameTable table;
    QStringList problems;
};

LoadedNames loadNames()
{
    LoadedNames loaded;
    QStringList builtInProblems;
    loaded.table.read(builtInSatelliteNames(), QStringLiteral("satellite-names.txt"), &builtInProblems);
    Q_ASSERT(builtInProblems.isEmpty()); // tst_tle reads it too

    const QString path = userSatelliteNamesPath();
    if (!QFileInfo::exists(path) && !QFileInfo(path).isSymLink())
        return loaded; // none: the built-in names alone
    // A regular file, read whole up to the cap: a FIFO or a device put
    // there is refused, never waited on.
    const input::BoundedRead read = input::readBoundedFile(path, kMostUserFileBytes);
    if (!read.ok()) {
        loaded.problems << QStringLiteral("%1: not read").arg(read.error);
        return loaded;
    }
    loaded.table.read(QString::fromUtf8(read.bytes), path, &loaded.problems);
    return loaded;
}

const LoadedNames &loadedNames()
{
    static const LoadedNames loaded = loadNames();
    return loaded;
}

} // namespace

QString satelliteNameKey(QStringView name)
{
    QString key;
    key.reserve(name.size());
    for (const QChar c : name)
        if (c.isLetterOrNumber())
            key += c.toUpper();
    return key;
}

QStringList satelliteNameKeys(const QString &name)
{
    QStringList keys{satelliteNameKey(name)};
    const qsizetype open = name.indexOf(QLatin1Char('('));
    if (open > 0)
        keys << satelliteNameKey(QStringView(name).left(open));
    for (qsizetype from = open; from >= 0; from = name.indexOf(QLatin1Char('('), from + 1)) {
        const qsizetype close = name.indexOf(QLatin1Char(')'), from);
        if (close < 0)
            break;
        keys << satelliteNameKey(QStringView(name).sliced(from + 1, close - from - 1));
    }
    keys.removeAll(QString());
    return keys;
}

void SatelliteNameTable::read(QStringView text, const QString &origin, QStringList *problems)
{
    int lineNumber = 0;
    for (QStringView line : text.split(QLatin1Char('\n'))) {
        ++lineNumber;
        const auto say = [&](const QString &why) { *problems << QStringLiteral("%1:%2: %3").arg(origin).arg(lineNumber).arg(why); };
        if (const qsizetype hash = line.indexOf(QLatin1Char('#')); hash >= 0)
            line = line.left(hash);
        line = line.trimmed();
        if (line.isEmpty())
            continue;
        qsizetype gap = 0;
        while (gap < line.size() && !line.at(gap).isSpace())
            ++gap;
        const QStringView number = line.left(gap);
        bool digits = number.size() <= kMostNumberDigits;
        for (const QChar c : number)
            digits = digits && c >= u'0' && c <= u'9';
        const int catalogueNumber = digits ? number.toInt() : 0;
        if (catalogueNumber <= 0) {
            say(QStringLiteral("'%1' is not a catalogue number; a line is a number and a name").arg(number.left(20)));
            continue;
        }
        const QString key = satelliteNameKey(line.sliced(gap));
        if (key.isEmpty()) {
            say(QStringLiteral("no name after the catalogue number %1").arg(catalogueNumber));
            continue;
        }
        m_numbers.insert(key, catalogueNumber);
    }
}

std::optional<int> SatelliteNameTable::catalogueNumber(const QString &key) const
{
    const auto found = m_numbers.constFind(key);
    if (found == m_numbers.cend())
        return std::nullopt;
    return *found;
}

const SatelliteNameTable &satelliteNames()
{
    return loadedNames().table;
}

const QStringList &satelliteNameProblems()
{
    return loadedNames().problems;
}

QString userSatelliteNamesPath()
{
    return QStandardPaths::writableLocation(QStandardPaths::GenericConfigLocation)
           + QStringLiteral("/Slew/satellite-names.txt");
}

} // namespace slew::sky
