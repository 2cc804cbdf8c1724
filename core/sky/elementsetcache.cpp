// SPDX-License-Identifier: GPL-3.0-or-later
#include "elementsetcache.h"

#include "elementsetcheck.h"

#include "input/atomicfile.h"
#include "input/boundedfile.h"

#include <QDir>
#include <QFileInfo>

namespace slew::sky {
namespace {

struct CachedCopy {
    bool present = false; // a file is there, readable or not
    QString error;        // why a file that is there cannot be used
    ElementSetRead read;
    ElementSetForm form = ElementSetForm::Tle;
    QDateTime savedAt;
};

// Slew 0.1 named its cached copies .tle, when they could hold nothing else:
// such a copy is still read until the next refresh writes the new name.
QString existingCopy(const QString &cacheFile)
{
    if (QFileInfo::exists(cacheFile) || !cacheFile.endsWith(QLatin1String(".elements")))
        return cacheFile;
    const QString older = cacheFile.chopped(9) + QStringLiteral(".tle");
    return QFileInfo::exists(older) ? older : cacheFile;
}

CachedCopy readCachedCopy(const QString &cacheFileName)
{
    CachedCopy copy;
    const QString cacheFile = existingCopy(cacheFileName);
    const QFileInfo info(cacheFile);
    if (!info.exists())
        return copy;
    copy.present = true;
    // A cache is ours, but a copy from before the cap (or a path replaced
    // by something else) must not stall the start: the same bounded read as
    // for a file the user names.
    const input::BoundedRead bytes = input::readBoundedFile(cacheFile, kMaxElementSetBytes);
    if (!bytes.ok()) {
        copy.error = QStringLiteral("the cached copy cannot be used: %1").arg(bytes.error);
        return copy;
    }
    const ElementSetText text = readElementSets(bytes.bytes);
    copy.read = text.read;
    copy.form = text.form;
    copy.savedAt = info.lastModified().toUTC();
    return copy;
}

SourceUpdate fromCache(const QUrl &url, const CachedCopy &copy, const QString &why)
{
    SourceUpdate update;
    ElementSetSourceStatus &s = update.status;
    s.url = url;
    QStringList errors;
    if (!why.isEmpty())
        errors << why;
    if (!copy.error.isEmpty())
        errors << copy.error;
    s.error = errors.join(QStringLiteral("; "));
    if (!copy.present || !copy.error.isEmpty())
        return update;
    update.sets = copy.read.sets;
    s.fromCache = true;
    s.cachedAt = copy.savedAt;
    s.refusals = copy.read.refusals;
    s.form = copy.form;
    s.setCount = int(copy.read.sets.size());
    return update;
}

QString save(const QString &cacheFile, const QByteArray &text)
{
    // Written whole or not at all: a crash or a full disk leaves the old copy.
    const QString why = input::saveAtomically(cacheFile, text);
    return why.isEmpty() ? why : QStringLiteral("the new copy was not cached: %1").arg(why);
}

} // namespace

SourceUpdate loadCachedSource(const QUrl &url, const QString &cacheFile)
{
    return fromCache(url, readCachedCopy(cacheFile), QString());
}

SourceUpdate keepCachedCopy(const QUrl &url, const QString &cacheFile, const QString &why)
{
    return fromCache(url, readCachedCopy(cacheFile), why);
}

SourceUpdate takeNewCopy(const QUrl &url, const QString &cacheFile, const QByteArray &text)
{
    const CachedCopy old = readCachedCopy(cacheFile);
    const ElementSetText freshText = readElementSets(text);
    const ElementSetRead &fresh = freshText.read;
    const QString refused = whyNotReplace(text, fresh, old.read.sets);
    if (!refused.isEmpty())
        return fromCache(url, old, refused);
    SourceUpdate update;
    ElementSetSourceStatus &s = update.status;
    s.url = url;
    s.fetched = true;
    s.cachedAt = QDateTime::currentDateTimeUtc();
    s.refusals = fresh.refusals;
    s.form = freshText.form;
    s.setCount = int(fresh.sets.size());
    s.error = save(cacheFile, text);
    update.sets = fresh.sets;
    return update;
}

SourceUpdate readLocalSource(const QUrl &url, const QString &cacheFile)
{
    const input::BoundedRead file = input::readBoundedFile(url.toLocalFile(), kMaxElementSetBytes);
    if (!file.ok())
        return keepCachedCopy(url, cacheFile, file.error);
    return takeNewCopy(url, cacheFile, file.bytes);
}

} // namespace slew::sky
