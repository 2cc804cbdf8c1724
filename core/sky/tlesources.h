// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where element sets come from: a list of URLs (CelesTrak-style group
// files) fetched over HTTP, each kept in a disk cache so Slew works offline
// from the last good copy. Fetching is asynchronous and never blocks the
// event loop; the cache is written atomically.

#include "tle.h"

#include <QDateTime>
#include <QList>
#include <QObject>
#include <QString>
#include <QUrl>

#include <optional>

class QNetworkAccessManager;
class QNetworkReply;

namespace slew::sky {

struct TleSourceStatus {
    QUrl url;
    bool fetched = false;      // this run's download worked
    bool fromCache = false;    // the sets come from the cache
    QDateTime cachedAt;        // when the cached copy was downloaded (UTC)
    QString error;             // why the download failed, if it did
    int setCount = 0;
    QList<TleRefusal> refusals;
};

class TleSources : public QObject {
    Q_OBJECT
public:
    explicit TleSources(const QString &cacheDirectory, QObject *parent = nullptr);

    void setUrls(const QList<QUrl> &urls);
    QList<QUrl> urls() const { return m_urls; }
    void setTimeoutMs(int ms) { m_timeoutMs = ms; }

    // Everything from the cache, with no network: what Slew starts with.
    void loadFromCache();
    // Download every URL; a URL that fails keeps its cached copy. Emits
    // finished() once all have answered.
    void refresh();
    bool isRefreshing() const { return m_pending > 0; }

    QList<Tle> sets() const;
    // The sets the index-th source holds now, as it gave them.
    QList<Tle> setsFrom(qsizetype index) const { return m_sets.value(index); }
    QList<TleSourceStatus> status() const { return m_status; }
    QString cacheFile(const QUrl &url) const;

signals:
    void finished();

private:
    void onReply(int index, QNetworkReply *reply);
    void loadCached(int index);

    QString m_cacheDirectory;
    QList<QUrl> m_urls;
    QList<TleSourceStatus> m_status;
    QList<QList<Tle>> m_sets;
    QNetworkAccessManager *m_network = nullptr;
    int m_pending = 0;
    int m_timeoutMs = 30000;
};

// Element sets older than a limit at a time: they predict worse every day
// (a LEO set a week old can be minutes off).
struct ElementAge {
    const Tle *tle = nullptr;
    double ageDays = 0;
};
QList<ElementAge> staleElements(const QList<Tle> &sets, double julianNow, double limitDays);

// The epoch of the newest set (a Julian date), none for no sets: how current
// a source is, as a group file holds sets of many ages.
std::optional<double> newestEpochJulian(const QList<Tle> &sets);

} // namespace slew::sky
