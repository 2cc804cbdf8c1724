// SPDX-License-Identifier: GPL-3.0-or-later
#include "elementsetsources.h"

#include "elementsetcache.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFutureWatcher>
#include <QHash>
#include <QNetworkAccessManager>
#include <QSettings>
#include <QStandardPaths>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>

namespace slew::sky {

std::optional<QUrl> elementSetUrl(const QString &text)
{
    const QUrl url(text.trimmed(), QUrl::StrictMode);
    const QString scheme = url.scheme().toLower();
    if (!url.isValid() || (scheme != u"http" && scheme != u"https" && scheme != u"file")
        || (scheme != u"file" && url.host().isEmpty()))
        return std::nullopt;
    return url;
}

QList<QUrl> savedElementSetUrls()
{
    QList<QUrl> urls;
    for (const QString &text : QSettings().value(QLatin1String(kElementSetUrlsSettingsKey)).toStringList())
        urls << QUrl(text);
    return urls;
}

void saveElementSetUrls(const QList<QUrl> &urls)
{
    QStringList texts;
    for (const QUrl &url : urls)
        texts << url.toString();
    QSettings().setValue(QLatin1String(kElementSetUrlsSettingsKey), texts);
}

QString elementSetCacheDirectory()
{
    return QStandardPaths::writableLocation(QStandardPaths::CacheLocation) + QStringLiteral("/element-sets");
}

QString elementSetCacheFile(const QString &directory, const QUrl &url)
{
    // One file a URL, named by its hash: URLs make poor file names. It holds
    // the source's answer as it came, in whichever form.
    const QByteArray hash = QCryptographicHash::hash(url.toEncoded(), QCryptographicHash::Sha1).toHex();
    return QDir(directory).filePath(QString::fromLatin1(hash.left(16)) + QStringLiteral(".elements"));
}

namespace {

QString setsText(int n)
{
    return n == 1 ? QStringLiteral("1 set") : QStringLiteral("%1 sets").arg(n);
}

QString refusedText(const ElementSetSourceStatus &s)
{
    return s.refusals.isEmpty() ? QString() : QStringLiteral(" (%1 refused)").arg(s.refusals.size());
}

} // namespace

QString describeSource(const ElementSetSourceStatus &s)
{
    const QString url = s.url.toString();
    if (s.fetched && s.error.isEmpty())
        return QStringLiteral("%1: replaced, %2%3").arg(url, setsText(s.setCount), refusedText(s));
    if (s.fetched)
        return QStringLiteral("%1: fetched %2%3, but %4").arg(url, setsText(s.setCount), refusedText(s), s.error);
    if (s.fromCache)
        return QStringLiteral("%1: kept the cached copy (%2 from %3): %4")
            .arg(url, setsText(s.setCount), s.cachedAt.toString(Qt::ISODate),
                 s.error.isEmpty() ? QStringLiteral("not refreshed") : s.error);
    return QStringLiteral("%1: failed, no cached copy: %2")
        .arg(url, s.error.isEmpty() ? QStringLiteral("not refreshed") : s.error);
}

bool sourceFailed(const ElementSetSourceStatus &s)
{
    return !s.fetched || !s.error.isEmpty();
}

ElementSetSources::ElementSetSources(const QString &cacheDirectory, QObject *parent)
    : QObject(parent)
    , m_cacheDirectory(cacheDirectory)
    , m_network(new QNetworkAccessManager(this))
{
}

// Jobs still running on a worker finish there and are dropped: they hold
// copies of what they need, never this object.
ElementSetSources::~ElementSetSources() = default;

void ElementSetSources::setUrls(const QList<QUrl> &urls)
{
    ++m_generation;
    qDeleteAll(m_downloads);
    m_urls = urls;
    m_status = QList<ElementSetSourceStatus>(urls.size());
    m_sets = QList<QList<ElementSet>>(urls.size());
    m_appliedSequence = QList<quint64>(urls.size(), 0);
    m_downloads = QList<BoundedDownload *>(urls.size(), nullptr);
    m_pending = 0;
    m_loading = 0;
    for (int i = 0; i < urls.size(); ++i)
        m_status[i].url = urls[i];
}

void ElementSetSources::loadFromCache(bool readFiles)
{
    if (m_urls.isEmpty()) {
        // Still from the event loop, as when there is something to read.
        QMetaObject::invokeMethod(
            this, [this] { stepDone(Step::Load); }, Qt::QueuedConnection);
        ++m_loading;
        return;
    }
    m_loading += int(m_urls.size());
    for (int i = 0; i < m_urls.size(); ++i) {
        const QUrl url = m_urls[i];
        const QString file = cacheFile(url);
        if (readFiles && url.scheme().compare(u"file", Qt::CaseInsensitive) == 0)
            startJob(i, Step::Load, [url, file] { return readLocalSource(url, file); });
        else
            startJob(i, Step::Load, [url, file] { return loadCachedSource(url, file); });
    }
}

void ElementSetSources::refresh()
{
    if (m_pending > 0)
        return;
    if (m_urls.isEmpty()) {
        ++m_pending;
        QMetaObject::invokeMethod(
            this, [this] { stepDone(Step::Refresh); }, Qt::QueuedConnection);
        return;
    }
    m_pending = int(m_urls.size());
    for (int i = 0; i < m_urls.size(); ++i) {
        const QUrl url = m_urls[i];
        const QString file = cacheFile(url);
        const QString scheme = url.scheme().toLower();
        if (scheme == u"file")
            // Never through the network manager: its file backend opens the
            // path on this thread, and a FIFO would block it.
            startJob(i, Step::Refresh, [url, file] { return readLocalSource(url, file); });
        else if (scheme == u"http" || scheme == u"https")
            startDownload(i);
        else
            startJob(i, Step::Refresh, [url, file] {
                return keepCachedCopy(url, file, QStringLiteral("not an http, https or file URL"));
            });
    }
}

void ElementSetSources::startDownload(int index)
{
    auto *download = new BoundedDownload(m_network, m_urls[index], m_limits, this);
    m_downloads[index] = download;
    connect(download, &BoundedDownload::done, this,
            [this, index, download](const QByteArray &body, const QString &error) {
                m_downloads[index] = nullptr;
                download->deleteLater();
                const QUrl url = m_urls[index];
                const QString file = cacheFile(url);
                if (error.isEmpty())
                    startJob(index, Step::Refresh, [url, file, body] { return takeNewCopy(url, file, body); });
                else
                    startJob(index, Step::Refresh, [url, file, error] { return keepCachedCopy(url, file, error); });
            });
}

void ElementSetSources::startJob(int index, Step step, std::function<SourceUpdate()> job)
{
    const quint64 generation = m_generation;
    const quint64 sequence = ++m_sequence;
    auto *watcher = new QFutureWatcher<SourceUpdate>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, index, step, generation, sequence] {
        watcher->deleteLater();
        if (generation != m_generation)
            return; // the list changed meanwhile
        apply(index, sequence, watcher->result());
        stepDone(step);
    });
    watcher->setFuture(QtConcurrent::run(std::move(job)));
}

void ElementSetSources::apply(int index, quint64 sequence, const SourceUpdate &update)
{
    // A cache load that ends after a refresh of the same source must not
    // bring back the copy the refresh replaced.
    if (sequence < m_appliedSequence[index])
        return;
    m_appliedSequence[index] = sequence;
    m_status[index] = update.status;
    m_sets[index] = update.sets;
}

void ElementSetSources::stepDone(Step step)
{
    int &left = step == Step::Load ? m_loading : m_pending;
    if (left == 0 || --left > 0)
        return;
    emit setsChanged();
    if (step == Step::Load)
        emit loaded();
    else
        emit finished();
}

QList<ElementSet> ElementSetSources::sets() const
{
    // A satellite listed by several sources is kept once, with its newest set.
    QList<ElementSet> all;
    for (const QList<ElementSet> &sets : m_sets)
        all += sets;
    return mergeByCatalogueNumber(all);
}

std::optional<double> newestEpochJulian(const QList<ElementSet> &sets)
{
    std::optional<double> newest;
    for (const ElementSet &t : sets)
        newest = std::max(newest.value_or(t.epochJulian()), t.epochJulian());
    return newest;
}

} // namespace slew::sky
