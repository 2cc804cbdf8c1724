// SPDX-License-Identifier: GPL-3.0-or-later
#include "elementsetoption.h"

#include "optionnames.h"

#include "sky/elementsetcache.h"
#include "sky/elementsetformat.h"
#include "sky/elementsetsources.h"

#include "input/logtext.h"

#include <QCommandLineParser>

namespace slew::cli {
namespace {

QString setsText(qsizetype n)
{
    return n == 1 ? QStringLiteral("1 set") : QStringLiteral("%1 sets").arg(n);
}

} // namespace

ElementSetOption cachedElementSets()
{
    ElementSetOption out;
    out.fromCache = true;
    const QString directory = sky::elementSetCacheDirectory();
    QList<sky::ElementSet> all;
    QStringList origins;
    for (const QUrl &url : sky::savedElementSetUrls()) {
        const sky::SourceUpdate cached = sky::loadCachedSource(url, sky::elementSetCacheFile(directory, url));
        if (!cached.status.fromCache)
            continue;
        all += cached.sets;
        origins << QStringLiteral("%1: %2 (%3), downloaded %4")
                       .arg(url.toString(), setsText(cached.sets.size()), sky::formName(cached.status.form),
                            cached.status.cachedAt.toString(Qt::ISODate));
        for (const sky::ElementSetRefusal &r : cached.status.refusals)
            out.skipped << QStringLiteral("%1 (cached): %2: skipped: %3").arg(url.toString(), r.where(), r.reason);
    }
    out.sets = sky::mergeByCatalogueNumber(all);
    if (origins.size() == 1)
        out.origin = QStringLiteral("the cached copy of %1").arg(origins.first());
    else if (!origins.isEmpty())
        out.origin = QStringLiteral("the cached copies of %1 sources, %2 in all: %3")
                         .arg(origins.size())
                         .arg(setsText(out.sets.size()))
                         .arg(origins.join(QStringLiteral("; ")));
    return out;
}

std::optional<ElementSetOption> readElementSetOption(const QCommandLineParser &parser, const OptionLabel &label,
                                                     QString *error)
{
    if (!parser.isSet(opt::tle)) {
        ElementSetOption cached = cachedElementSets();
        if (cached.sets.isEmpty()) {
            *error = QStringLiteral("no element sets: give --tle FILE, or refresh the window's sources with "
                                    "slew --update-elements URL (such as %1)")
                         .arg(QLatin1String(sky::kExampleElementSetUrl));
            return std::nullopt;
        }
        return cached;
    }
    const QString path = parser.value(opt::tle);
    const sky::ElementSetFile file = sky::readElementSetFile(path);
    if (!file.error.isEmpty()) {
        *error = QStringLiteral("%1: %2").arg(label(opt::tle), file.error);
        return std::nullopt;
    }
    ElementSetOption out;
    out.sets = file.sets;
    const QString shownPath = input::loggableText(path, 120);
    out.origin = QStringLiteral("%1: %2 (%3)").arg(shownPath, setsText(file.sets.size()), sky::formName(file.form));
    for (const sky::ElementSetRefusal &r : file.refusals)
        out.skipped << QStringLiteral("%1:%2: skipped: %3").arg(shownPath, r.place(), r.reason);
    if (file.duplicates > 0)
        out.skipped << QStringLiteral("%1: %2 repeat a satellite listed before; the newest epoch of each is used")
                           .arg(shownPath, setsText(file.duplicates));
    return out;
}

} // namespace slew::cli
