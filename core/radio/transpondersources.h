// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where transponders come from: SatNOGS DB's transmitter list (its API over
// HTTPS, or a saved copy) and Gpredict's .trsp files, each named by a URL
// (https://, or file:// for a local file) and kept in a disk cache beside
// the element sets, so the radio works offline from the last good copy.
//
// The same rules as the element sets' sources (sky/elementsetsources.h), with the
// same download code (sky/boundeddownload.h): a download is bounded in
// size (the transmitter list's cap, transponderimport.h) and in time;
// files are read with the bounded reader; reading, parsing and writing the
// cache happen on worker threads; the cache is written atomically; and a
// new copy replaces the cached one only when it reads cleanly and keeps
// most of the satellites the old copy had (a login page or a cut-short
// transfer must not throw a good copy away).
//
// A .trsp source (its URL's path ends in .trsp) is one satellite's, named
// after its catalogue number as Gpredict names them (25544.trsp); any other
// source is read as a SatNOGS DB transmitter list.

#include "transponderset.h"

#include "sky/boundeddownload.h"

#include <QDateTime>
#include <QList>
#include <QObject>
#include <QString>
#include <QStringList>
#include <QUrl>

#include <functional>
#include <optional>

class QNetworkAccessManager;

namespace slew::radio {

class TransponderWatch;

// The settings key of the list of sources, and the one to suggest.
inline constexpr char kTransponderUrlsSettingsKey[] = "radio/transponderUrls";
inline constexpr char kSatnogsTransmittersUrl[] = "https://db.satnogs.org/api/transmitters/?format=json";
inline constexpr int kTransponderSilenceMs = 30000;
inline constexpr int kTransponderTransferMs = 120000;

QList<QUrl> savedTransponderUrls();
void saveTransponderUrls(const QList<QUrl> &urls);

// A source as the operator names one: an https:// or http:// URL, a
// file:// URL or a local file's path. A local file must be there and be a
// .trsp named after its satellite's catalogue number (25544.trsp) or a
// SatNOGS DB list (.json). Nothing, with *error naming what was given and
// why not, otherwise.
std::optional<QUrl> transponderSourceUrl(const QString &text, QString *error);
// Beside the element sets' cache.
QString transponderCacheDirectory();
// The cached copy of one source in `directory`: HASH.json, or HASH/25544.trsp
// (a .trsp file's name says its satellite).
QString transponderCacheFile(const QString &directory, const QUrl &url);

struct TransponderSourceStatus {
    QUrl url;
    bool fetched = false;   // this refresh brought a new copy, and it was taken
    bool fromCache = false; // the transponders come from the cached copy
    QDateTime cachedAt;     // when the copy held now was saved (UTC)
    QString error;          // why a refresh or the cache failed, or the new copy was not taken
    int count = 0;
    QStringList skipped;    // entries the reader skipped, as it reported them
};

// One line a source after a refresh, for the log and the terminal.
QString describeTransponderSource(const TransponderSourceStatus &status);

class TransponderSources : public QObject {
    Q_OBJECT
public:
    explicit TransponderSources(const QString &cacheDirectory, QObject *parent = nullptr);
    ~TransponderSources() override;

    // A new list drops a load or refresh under way and empties the set.
    void setUrls(const QList<QUrl> &urls);
    QList<QUrl> urls() const { return m_urls; }
    void setSilenceLimitMs(int ms) { m_limits.silenceMs = ms; }
    void setTransferLimitMs(int ms) { m_limits.transferMs = ms; }

    // Every source from the cache, no network; loaded() when done.
    void loadFromCache();
    // Every source fetched; one whose new copy fails keeps its cached copy.
    // finished() once all have answered.
    void refresh();
    bool isBusy() const { return m_pending > 0; }
    // From now on the list saved in the settings and the cached copies are
    // followed as another Slew (slew --update-transponders) changes them
    // (transponderwatch.h); the watch says what it took. Asked again, the
    // same watch.
    TransponderWatch *followSaved();

    // Every source's transponders, merged in the order of the list (the
    // first source's copy of a repeated transponder is kept).
    const TransponderSet &transponders() const { return m_set; }
    QList<TransponderSourceStatus> status() const { return m_status; }
    QString cacheFile(const QUrl &url) const { return transponderCacheFile(m_cacheDirectory, url); }

    struct Update {
        TransponderSourceStatus status;
        QList<Transponder> transponders;
    };

signals:
    void loaded();
    void finished();
    // After loaded() or finished(): transponders() and status() are new.
    void transpondersChanged();

private:
    void startDownload(int index);
    void startJob(int index, std::function<Update()> job);
    void jobDone();

    QString m_cacheDirectory;
    QList<QUrl> m_urls;
    QList<TransponderSourceStatus> m_status;
    QList<QList<Transponder>> m_bySource;
    QList<quint64> m_appliedSequence;
    QList<sky::BoundedDownload *> m_downloads;
    TransponderSet m_set;
    TransponderWatch *m_watch = nullptr;
    QNetworkAccessManager *m_network = nullptr;
    sky::DownloadLimits m_limits;
    quint64 m_generation = 0;
    quint64 m_sequence = 0;
    int m_pending = 0;
    bool m_refreshing = false;
};

// Why `fresh` must not replace a cached copy that held `previous`, or empty.
// At most one entry in ten skipped (one always allowed), and at least half
// of the old copy's satellites kept.
QString whyNotReplaceTransponders(const QList<Transponder> &fresh, int skipped, const QList<Transponder> &previous);

} // namespace slew::radio
