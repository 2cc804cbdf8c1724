// SPDX-License-Identifier: GPL-3.0-or-later
#include "elementsetcheck.h"

#include <QSet>

namespace slew::sky {
namespace {

// An HTML page starts with '<', as OMM XML does, and says what it is in
// its first tags (a doctype or <html>).
bool looksLikeHtml(const QByteArray &text)
{
    for (const char c : text) {
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n')
            continue;
        if (c != '<')
            return false;
        const QByteArray head = text.left(1024).toLower();
        return head.contains("<html") || head.contains("<!doctype html");
    }
    return false;
}

QString setsText(qsizetype n)
{
    return n == 1 ? QStringLiteral("1 set") : QStringLiteral("%1 sets").arg(n);
}

} // namespace

QString whyNotReplace(const QByteArray &text, const ElementSetRead &fresh, const QList<ElementSet> &previous)
{
    // An HTML page first: it starts with '<', as OMM XML does, and then
    // reads as broken XML with no sets, which would hide what it is.
    if (looksLikeHtml(text))
        return QStringLiteral("the answer is an HTML page, not an element-set file");
    if (fresh.sets.isEmpty())
        return fresh.refusals.isEmpty() ? QStringLiteral("the answer holds no element sets")
                                        : QStringLiteral("the answer holds no element sets (%1: %2)")
                                              .arg(fresh.refusals.first().where(), fresh.refusals.first().reason);
    const qsizetype refused = fresh.refusals.size();
    if (refused > 1 && refused * 10 > fresh.sets.size() * kMaxRefusedPerTenSets)
        return QStringLiteral("the answer does not read cleanly: %1 entries refused beside %2 (at most one in ten "
                              "may be; the first at %3: %4)")
            .arg(refused)
            .arg(setsText(fresh.sets.size()))
            .arg(fresh.refusals.first().where())
            .arg(fresh.refusals.first().reason);
    if (previous.isEmpty())
        return {};
    QSet<int> now;
    for (const ElementSet &t : fresh.sets)
        now.insert(t.catalogueNumber);
    QSet<int> before;
    for (const ElementSet &t : previous)
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
