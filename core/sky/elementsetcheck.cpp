// SPDX-License-Identifier: GPL-3.0-or-later
#include "elementsetcheck.h"

#include <QSet>

namespace slew::sky {
namespace {

// An HTML page starts with '<' (a doctype, a tag or a comment); an element
// set file never does.
bool looksLikeHtml(const QByteArray &text)
{
    for (const char c : text) {
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n')
            continue;
        return c == '<';
    }
    return false;
}

QString setsText(qsizetype n)
{
    return n == 1 ? QStringLiteral("1 set") : QStringLiteral("%1 sets").arg(n);
}

} // namespace

QString whyNotReplace(const QByteArray &text, const TleReadResult &fresh, const QList<Tle> &previous)
{
    if (fresh.sets.isEmpty())
        return QStringLiteral("the answer holds no element sets");
    if (looksLikeHtml(text))
        return QStringLiteral("the answer is an HTML page, not an element-set file (it holds %1)")
            .arg(setsText(fresh.sets.size()));
    const qsizetype refused = fresh.refusals.size();
    if (refused > 1 && refused * 10 > fresh.sets.size() * kMaxRefusedPerTenSets)
        return QStringLiteral("the answer does not read cleanly: %1 entries refused beside %2 (at most one in ten "
                              "may be; the first at line %3: %4)")
            .arg(refused)
            .arg(setsText(fresh.sets.size()))
            .arg(fresh.refusals.first().line)
            .arg(fresh.refusals.first().reason);
    if (previous.isEmpty())
        return {};
    QSet<int> now;
    for (const Tle &t : fresh.sets)
        now.insert(t.catalogueNumber);
    QSet<int> before;
    for (const Tle &t : previous)
        before.insert(t.catalogueNumber);
    qsizetype kept = 0;
    for (const int number : before)
        kept += now.contains(number) ? 1 : 0;
    if (double(kept) < kMinShareOfOldSatellitesKept * double(before.size()))
        return QStringLiteral("the answer holds %1 and keeps %2 of the %3 satellites in the cached copy (at least "
                              "half must stay)")
            .arg(setsText(fresh.sets.size()))
            .arg(kept)
            .arg(before.size());
    return {};
}

} // namespace slew::sky
