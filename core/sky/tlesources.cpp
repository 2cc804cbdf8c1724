// SPDX-License-Identifier: GPL-3.0-or-later
#include "tlesources.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QNetworkAccessManager>
#include <QNetworkReply>
#include <QNetworkRequest>
#include <QSaveFile>

#include <algorithm>

namespace slew::sky {

TleSources::TleSources(const QString &cacheDirectory, QObject *parent)
    : QObject(parent)
    , m_cacheDirectory(cacheDirectory)
    , m_network(new QNetworkAccessManager(this))
{
}

void TleSources::setUrls(const QList<QUrl> &urls)
{
    m_urls = urls;
    m_status = QList<TleSourceStatus>(urls.size());
    m_sets = QList<QList<Tle>>(urls.size());
    for (int i = 0; i < urls.size(); ++i)
        m_status[i].url = urls[i];
}

QString TleSources::cacheFile(const QUrl &url) const
{
    // One file a URL, named by its hash: URLs make poor file names.
    const QByteArray hash = QCryptographicHash::hash(url.toEncoded(), QCryptographicHash::Sha1).toHex();
    return QDir(m_cacheDirectory).filePath(QString::fromLatin1(hash.left(16)) + QStringLiteral(".tle"));
}

void TleSources::loadCached(int index)
{
    TleSourceStatus &s = m_status[index];
    QFile file(cacheFile(s.url));
    if (!file.open(QIODevice::ReadOnly)) {
        s.fromCache = false;
        m_sets[index].clear();
        s.setCount = 0;
        return;
    }
    const TleReadResult read = readTleText(QString::fromUtf8(file.readAll()));
    m_sets[index] = read.sets;
    s.refusals = read.refusals;
    s.setCount = int(read.sets.size());
    s.fromCache = true;
    s.cachedAt = QFileInfo(file).lastModified().toUTC();
}

void TleSources::loadFromCache()
{
    for (int i = 0; i < m_urls.size(); ++i)
        loadCached(i);
}

void TleSources::refresh()
{
    if (m_pending > 0)
        return;
    m_pending = int(m_urls.size());
    if (m_pending == 0) {
        emit finished();
        return;
    }
    for (int i = 0; i < m_urls.size(); ++i) {
        QNetworkRequest request(m_urls[i]);
        request.setTransferTimeout(m_timeoutMs);
        request.setAttribute(QNetworkRequest::RedirectPolicyAttribute, QNetworkRequest::NoLessSafeRedirectPolicy);
        QNetworkReply *reply = m_network->get(request);
        connect(reply, &QNetworkReply::finished, this, [this, i, reply] { onReply(i, reply); });
    }
}

void TleSources::onReply(int index, QNetworkReply *reply)
{
    reply->deleteLater();
    TleSourceStatus &s = m_status[index];
    const QByteArray body = reply->readAll();
    const TleReadResult read = readTleText(QString::fromUtf8(body));
    if (reply->error() != QNetworkReply::NoError) {
        s.error = reply->errorString();
        s.fetched = false;
        loadCached(index);
    } else if (read.sets.isEmpty()) {
        // A page that holds no element sets (an error page, a login) must
        // not replace a good cached copy.
        s.error = QStringLiteral("the answer holds no element sets");
        s.fetched = false;
        loadCached(index);
    } else {
        QDir().mkpath(m_cacheDirectory);
        QSaveFile file(cacheFile(s.url));
        if (file.open(QIODevice::WriteOnly)) {
            file.write(body);
            file.commit();
        }
        m_sets[index] = read.sets;
        s.refusals = read.refusals;
        s.setCount = int(read.sets.size());
        s.fetched = true;
        s.fromCache = false;
        s.error.clear();
        s.cachedAt = QDateTime::currentDateTimeUtc();
    }
    if (--m_pending == 0)
        emit finished();
}

QList<Tle> TleSources::sets() const
{
    // A satellite listed by several sources is kept once, with its newest set.
    QList<Tle> all;
    QHash<int, qsizetype> where;
    for (const QList<Tle> &sets : m_sets) {
        for (const Tle &t : sets) {
            const auto it = where.find(t.catalogueNumber);
            if (it == where.end()) {
                where.insert(t.catalogueNumber, all.size());
                all.append(t);
            } else if (all[*it].epochJulian() < t.epochJulian()) {
                all[*it] = t;
            }
        }
    }
    return all;
}

QList<ElementAge> staleElements(const QList<Tle> &sets, double julianNow, double limitDays)
{
    QList<ElementAge> stale;
    for (const Tle &t : sets) {
        const double age = julianNow - t.epochJulian();
        if (age > limitDays)
            stale.append({&t, age});
    }
    return stale;
}

std::optional<double> newestEpochJulian(const QList<Tle> &sets)
{
    std::optional<double> newest;
    for (const Tle &t : sets)
        newest = std::max(newest.value_or(t.epochJulian()), t.epochJulian());
    return newest;
}

} // namespace slew::sky
