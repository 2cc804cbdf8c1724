// SPDX-License-Identifier: GPL-3.0-or-later
#include "transpondersources.h"

#include "transponderimport.h"
#include "transponderwatch.h"

#include "input/atomicfile.h"
#include "input/boundedfile.h"
#include "input/logtext.h"
#include "sky/elementsetsources.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QNetworkAccessManager>
#include <QSet>
#include <QSettings>
#include <QtConcurrent/QtConcurrentRun>

namespace slew::radio {

namespace {

bool isTrsp(const QUrl &url)
{
    return url.path().endsWith(QLatin1String(".trsp"), Qt::CaseInsensitive);
}

// A source's bytes as transponders, by its format.
TransponderImport readSource(const QUrl &url, const QByteArray &bytes)
{
    const QString name = url.isLocalFile() ? url.toLocalFile() : url.toString();
    if (isTrsp(url)) {
        const std::optional<int> norad = noradIdFromTrspFileName(url.path());
        if (!norad) {
            TransponderImport refused;
            refused.error = QObject::tr("%1: a .trsp file is named after its satellite's catalogue number (25544.trsp)")
                                .arg(name);
            return refused;
        }
        return readGpredictTrsp(bytes, name, *norad);
    }
    return readSatnogsTransmitters(bytes, name);
}

qint64 capFor(const QUrl &url)
{
    return isTrsp(url) ? kLargestTrspFile : kLargestTransmitterList;
}

struct CachedCopy {
    bool present = false;
    QString error;
    TransponderImport read;
    QDateTime savedAt;
};

CachedCopy readCachedCopy(const QUrl &url, const QString &file)
{
    CachedCopy copy;
    const QFileInfo info(file);
    if (!info.exists())
        return copy;
    copy.present = true;
    const input::BoundedRead bytes = input::readBoundedFile(file, capFor(url));
    if (!bytes.ok()) {
        copy.error = QObject::tr("the cached copy cannot be used: %1").arg(bytes.error);
        return copy;
    }
    copy.read = readSource(url, bytes.bytes);
    if (!copy.read.ok())
        copy.error = QObject::tr("the cached copy cannot be used: %1").arg(copy.read.error);
    copy.savedAt = info.lastModified().toUTC();
    return copy;
}

TransponderSources::Update fromCache(const QUrl &url, const CachedCopy &copy, const QString &why)
{
    TransponderSources::Update update;
    TransponderSourceStatus &s = update.status;
    s.url = url;
    QStringList errors;
    if (!why.isEmpty())
        errors << why;
    if (!copy.error.isEmpty())
        errors << copy.error;
    s.error = errors.join(QLatin1String("; "));
    if (!copy.present || !copy.error.isEmpty())
        return update;
    update.transponders = copy.read.transponders;
    s.fromCache = true;
    s.cachedAt = copy.savedAt;
    s.count = int(copy.read.transponders.size());
    s.skipped = copy.read.skipReport();
    return update;
}

TransponderSources::Update takeNewCopy(const QUrl &url, const QString &file, const QByteArray &bytes)
{
    const CachedCopy old = readCachedCopy(url, file);
    const TransponderImport fresh = readSource(url, bytes);
    const QString refused = fresh.ok() ? whyNotReplaceTransponders(fresh.transponders, fresh.skippedCount,
                                                                   old.read.transponders)
                                       : QObject::tr("the new copy was not taken: %1").arg(fresh.error);
    if (!refused.isEmpty())
        return fromCache(url, old, refused);
    TransponderSources::Update update;
    TransponderSourceStatus &s = update.status;
    s.url = url;
    s.fetched = true;
    s.cachedAt = QDateTime::currentDateTimeUtc();
    s.count = int(fresh.transponders.size());
    s.skipped = fresh.skipReport();
    s.error = input::saveAtomically(file, bytes);
    update.transponders = fresh.transponders;
    return update;
}

TransponderSources::Update readLocalSource(const QUrl &url, const QString &file)
{
    const input::BoundedRead read = input::readBoundedFile(url.toLocalFile(), capFor(url));
    if (!read.ok())
        return fromCache(url, readCachedCopy(url, file), read.error);
    return takeNewCopy(url, file, read.bytes);
}

} // namespace

QList<QUrl> savedTransponderUrls()
{
    QList<QUrl> urls;
    for (const QString &text : QSettings().value(QLatin1String(kTransponderUrlsSettingsKey)).toStringList())
        urls << QUrl(text);
    return urls;
}

void saveTransponderUrls(const QList<QUrl> &urls)
{
    QStringList texts;
    for (const QUrl &url : urls)
        texts << url.toString();
    QSettings().setValue(QLatin1String(kTransponderUrlsSettingsKey), texts);
}

std::optional<QUrl> transponderSourceUrl(const QString &text, QString *error)
{
    const QString given = text.trimmed();
    const QString shown = input::loggableText(given, 80);
    auto refuse = [&](const QString &why) -> std::optional<QUrl> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    if (given.isEmpty())
        return refuse(QObject::tr("name a transponder source: a .trsp or .json file, or an https:// URL"));
    // A path as typed (no scheme, or a Windows-like drive letter) is a local file.
    const QUrl asUrl(given, QUrl::StrictMode);
    const QString scheme = asUrl.scheme().toLower();
    if (scheme == u"http" || scheme == u"https") {
        if (!asUrl.isValid() || asUrl.host().isEmpty())
            return refuse(QObject::tr("'%1' is not a URL Slew can fetch: it names no host").arg(shown));
        return asUrl;
    }
    if (!scheme.isEmpty() && scheme != u"file")
        return refuse(QObject::tr("'%1': a source is an https:// or http:// URL, or a file").arg(shown));
    const QString path = scheme == u"file" ? asUrl.toLocalFile() : given;
    const QFileInfo file(path);
    if (!file.exists())
        return refuse(QObject::tr("'%1': no such file").arg(shown));
    if (!file.isFile() || !file.isReadable())
        return refuse(QObject::tr("'%1' is not a file Slew can read").arg(shown));
    const QUrl url = QUrl::fromLocalFile(file.absoluteFilePath());
    if (isTrsp(url)) {
        if (!noradIdFromTrspFileName(url.path()))
            return refuse(QObject::tr("'%1': a .trsp file is named after its satellite's catalogue number "
                                      "(25544.trsp)")
                              .arg(shown));
    } else if (file.suffix().compare(QLatin1String("json"), Qt::CaseInsensitive) != 0) {
        return refuse(QObject::tr("'%1': a transponder file is a Gpredict .trsp or a SatNOGS DB .json list")
                          .arg(shown));
    }
    return url;
}

QString transponderCacheDirectory()
{
    return QFileInfo(sky::elementSetCacheDirectory()).dir().filePath(QStringLiteral("transponders"));
}

QString transponderCacheFile(const QString &directory, const QUrl &url)
{
    // One file a URL, named by its hash: URLs make poor file names. A .trsp
    // file keeps its own name (the satellite's number) in a folder so named.
    const QString hash =
        QString::fromLatin1(QCryptographicHash::hash(url.toEncoded(), QCryptographicHash::Sha1).toHex().left(16));
    if (isTrsp(url))
        return QDir(directory).filePath(hash + QLatin1Char('/') + QFileInfo(url.path()).fileName());
    return QDir(directory).filePath(hash + QStringLiteral(".json"));
}

QString whyNotReplaceTransponders(const QList<Transponder> &fresh, int skipped, const QList<Transponder> &previous)
{
    const int read = int(fresh.size()) + skipped;
    if (skipped > std::max(1, read / 10))
        return QObject::tr("the new copy was not taken: %1 of its %2 entries could not be read").arg(skipped).arg(read);
    QSet<int> before, after;
    for (const Transponder &t : previous)
        before.insert(t.noradId);
    for (const Transponder &t : fresh)
        after.insert(t.noradId);
    const int kept = int((before & after).size());
    if (!before.isEmpty() && kept < before.size() / 2)
        return QObject::tr("the new copy was not taken: it has %1 of the %2 satellites the cached copy has")
            .arg(kept)
            .arg(before.size());
    return {};
}

QString describeTransponderSource(const TransponderSourceStatus &s)
{
    const QString url = s.url.toString();
    const QString count = QObject::tr("%n transponder(s)", nullptr, s.count);
    if (s.fetched && s.error.isEmpty())
        return QObject::tr("%1: replaced, %2").arg(url, count);
    if (s.fetched)
        return QObject::tr("%1: fetched %2, but %3").arg(url, count, s.error);
    if (s.fromCache)
        return QObject::tr("%1: kept the cached copy (%2 from %3): %4")
            .arg(url, count, s.cachedAt.toString(Qt::ISODate), s.error.isEmpty() ? QObject::tr("not refreshed") : s.error);
    return QObject::tr("%1: failed, no cached copy: %2").arg(url, s.error.isEmpty() ? QObject::tr("not refreshed") : s.error);
}

TransponderSources::TransponderSources(const QString &cacheDirectory, QObject *parent)
    : QObject(parent), m_cacheDirectory(cacheDirectory), m_network(new QNetworkAccessManager(this)),
      m_limits{kLargestTransmitterList, kTransponderSilenceMs, kTransponderTransferMs}
{
}

// Jobs still running on a worker finish there and are dropped: they hold
// copies of what they need, never this object.
TransponderSources::~TransponderSources() = default;

void TransponderSources::setUrls(const QList<QUrl> &urls)
{
    ++m_generation;
    qDeleteAll(m_downloads);
    m_urls = urls;
    m_status = QList<TransponderSourceStatus>(urls.size());
    m_bySource = QList<QList<Transponder>>(urls.size());
    m_appliedSequence = QList<quint64>(urls.size(), 0);
    m_downloads = QList<sky::BoundedDownload *>(urls.size(), nullptr);
    m_pending = 0;
    m_set = TransponderSet();
    for (int i = 0; i < urls.size(); ++i)
        m_status[i].url = urls[i];
}

TransponderWatch *TransponderSources::followSaved()
{
    if (!m_watch)
        m_watch = new TransponderWatch(this, this);
    return m_watch;
}

void TransponderSources::loadFromCache()
{
    if (m_pending > 0)
        return;
    m_refreshing = false;
    if (m_urls.isEmpty()) {
        ++m_pending;
        QMetaObject::invokeMethod(this, &TransponderSources::jobDone, Qt::QueuedConnection);
        return;
    }
    m_pending = int(m_urls.size());
    for (int i = 0; i < m_urls.size(); ++i) {
        const QUrl url = m_urls[i];
        const QString file = cacheFile(url);
        startJob(i, [url, file] { return fromCache(url, readCachedCopy(url, file), QString()); });
    }
}

void TransponderSources::refresh()
{
    if (m_pending > 0)
        return;
    m_refreshing = true;
    if (m_urls.isEmpty()) {
        ++m_pending;
        QMetaObject::invokeMethod(this, &TransponderSources::jobDone, Qt::QueuedConnection);
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
            startJob(i, [url, file] { return readLocalSource(url, file); });
        else if (scheme == u"http" || scheme == u"https")
            startDownload(i);
        else
            startJob(i, [url, file] {
                return fromCache(url, readCachedCopy(url, file), QObject::tr("not an http, https or file URL"));
            });
    }
}

void TransponderSources::startDownload(int index)
{
    sky::DownloadLimits limits = m_limits;
    limits.maxBytes = capFor(m_urls[index]);
    auto *download = new sky::BoundedDownload(m_network, m_urls[index], limits, this);
    m_downloads[index] = download;
    connect(download, &sky::BoundedDownload::done, this,
            [this, index, download](const QByteArray &body, const QString &error) {
                m_downloads[index] = nullptr;
                download->deleteLater();
                const QUrl url = m_urls[index];
                const QString file = cacheFile(url);
                if (error.isEmpty())
                    startJob(index, [url, file, body] { return takeNewCopy(url, file, body); });
                else
                    startJob(index, [url, file, error] { return fromCache(url, readCachedCopy(url, file), error); });
            });
}

void TransponderSources::startJob(int index, std::function<Update()> job)
{
    const quint64 generation = m_generation;
    const quint64 sequence = ++m_sequence;
    auto *watcher = new QFutureWatcher<Update>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, index, generation, sequence] {
        watcher->deleteLater();
        if (generation != m_generation)
            return; // the list changed meanwhile
        // A cache load that ends after a refresh of the same source must not
        // bring back the copy the refresh replaced.
        if (sequence >= m_appliedSequence[index]) {
            m_appliedSequence[index] = sequence;
            const Update update = watcher->result();
            m_status[index] = update.status;
            m_bySource[index] = update.transponders;
        }
        jobDone();
    });
    watcher->setFuture(QtConcurrent::run(std::move(job)));
}

void TransponderSources::jobDone()
{
    if (m_pending == 0 || --m_pending > 0)
        return;
    m_set = TransponderSet();
    for (const QList<Transponder> &list : std::as_const(m_bySource))
        m_set.merge(list);
    emit transpondersChanged();
    if (m_refreshing)
        emit finished();
    else
        emit loaded();
}

} // namespace slew::radio
