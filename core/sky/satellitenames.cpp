// SPDX-License-Identifier: GPL-3.0-or-later
#include "satellitenames.h"

#include <array>

namespace slew::sky {

namespace {

struct KnownName {
    int catalogueNumber;
    const char *name;
};

// AMSAT's OSCAR designations and the satellites' own or former names, as
// AMSAT's satellite status page and its "OSCAR numbers" list give them.
// Only names an element set may lack: where CelesTrak writes the
// designation in parentheses ("FOX-1B (AO-91)"), the set is found by it
// anyway. Checked against the catalogue numbers of CelesTrak's amateur
// group.
constexpr std::array<KnownName, 33> kAmsatNames{{
    {7530, "AO-7"},           {7530, "OSCAR 7"},        {14781, "UO-11"},       {14781, "UOSAT 2"},
    {20480, "FO-20"},         {20480, "JAS-1B"},        {22825, "AO-27"},       {24278, "FO-29"},
    {24278, "JAS-2"},         {25544, "ISS"},           {25544, "ARISS"},       {27607, "SO-50"},
    {27607, "SAUDISAT-1C"},   {39444, "AO-73"},         {39444, "FUNCUBE-1"},   {40654, "NO-84"},
    {40654, "PSAT"},          {40931, "IO-86"},         {40931, "LAPAN-A2"},    {42017, "EO-88"},
    {42017, "NAYIF-1"},       {43017, "AO-91"},         {43017, "FOX-1B"},      {43137, "AO-92"},
    {43137, "FOX-1D"},        {43678, "PO-101"},        {43678, "DIWATA-2"},    {43700, "QO-100"},
    {43700, "ES'HAIL-2"},     {43803, "JO-97"},         {43937, "FO-99"},       {44909, "RS-44"},
    {44909, "DOSAAF-85"},
}};

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

std::optional<int> amsatCatalogueNumber(const QString &key)
{
    if (key.isEmpty())
        return std::nullopt;
    for (const KnownName &n : kAmsatNames)
        if (satelliteNameKey(QString::fromLatin1(n.name)) == key)
            return n.catalogueNumber;
    return std::nullopt;
}

} // namespace slew::sky
