// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where element sets come from: a list of URLs (CelesTrak's GP queries and
// group files over HTTP(S), in any of the five forms, or local files as
// file:// URLs), each kept in a disk cache, as it was downloaded, so Slew
// works offline from the last good copy.
//
// Nothing here blocks the event loop: downloads are bounded in size and
// time (BoundedDownload), and reading files, parsing and writing the cache
// happen on worker threads (elementsetcache.h). A new copy replaces the
// cached one only when it is plausible (elementsetcheck.h); the cache is
// written atomically. The window and `slew --update-elements` share this
// class, its cache directory and the saved list of sources.

#include "boundeddownload.h"
#include "elementage.h"
#include "elementsetformat.h"

#include <QDateTime>
#include <QList>
#include <QObject>
#include <QString>
#include <QUrl>

#include <functional>
#include <optional>

class QNetworkAccessManager;

namespace slew::sky {

struct SourceUpdate;

// The limits of one refresh of one source, stated in README and in the
// messages that report them.
inline constexpr qint64 kMaxElementSetBytes = kLargestElementFile; // elementset.h: one cap for files and downloads
inline constexpr int kElementSetSilenceMs = 30000;
inline constexpr int kElementSetTransferMs = 120000;

// The window's list of sources in the settings (Sky → Element sets…), which
// `slew --update-elements` refreshes when it is given no URL.
inline constexpr char kElementSetUrlsSettingsKey[] = "sky/elementSetUrls";
// A source to suggest where none is kept yet.
// CSV, CelesTrak's GP form with room for nine-digit catalogue numbers: a
// FORMAT=tle query stops at the last five-digit object.
inline constexpr char kExampleElementSetUrl[] = "https://celestrak.org/NORAD/elements/gp.php?GROUP=amateur&FORMAT=csv";

QList<QUrl> savedElementSetUrls();
// A source as a user types it: an http or https URL with a host, or a file
// URL; nothing for anything else.
std::optional<QUrl> elementSetUrl(const QString &text);
void saveElementSetUrls(const QList<QUrl> &urls);
// Where the cached copies live: the same for the window and the command line.
QString elementSetCacheDirectory();
// The cached copy of one source in `directory`.
QString elementSetCacheFile(const QString &directory, const QUrl &url);

struct ElementSetSourceStatus {
    QUrl url;
    bool fetched = false;      // this run's refresh brought a new copy, and it was taken
    bool fromCache = false;    // the sets come from the cached copy
    QDateTime cachedAt;        // when the copy held now was downloaded (UTC)
    ElementSetForm form = ElementSetForm::Tle; // what the copy held now is written in
    QString error;             // why a refresh or the cache failed, or the new copy was not taken
    int setCount = 0;
    QList<ElementSetRefusal> refusals;
};

// One line about a source after a refresh, for the log and the terminal:
// "URL: replaced, 979 sets", "URL: kept the cached copy (979 sets): why".
QString describeSource(const ElementSetSourceStatus &status);
// True when the refresh of this source did not end in a new copy, cached.
bool sourceFailed(const ElementSetSourceStatus &status);

class ElementSetSources : public QObject {
    Q_OBJECT
public:
    explicit ElementSetSources(const QString &cacheDirectory, QObject *parent = nullptr);
    ~ElementSetSources() override;

    // A new list drops a load or a refresh under way (its signal does not
    // come) and empties the sets until loadFromCache() or refresh().
    void setUrls(const QList<QUrl> &urls);
    QList<QUrl> urls() const { return m_urls; }
    // The limits of each download (the defaults above); tests shorten them.
    void setSilenceLimitMs(int ms) { m_limits.silenceMs = ms; }
    void setTransferLimitMs(int ms) { m_limits.transferMs = ms; }

    // Everything from the cache, with no network: what Slew starts with.
    // Read on worker threads; emits loaded() (and setsChanged()) when done.
    // With `readFiles`, a local file is read afresh rather than from its
    // cached copy (a file just added has none): still no network.
    void loadFromCache(bool readFiles = false);
    bool isLoading() const { return m_loading > 0; }
    // Fetch every URL; a source whose new copy fails or is not plausible
    // keeps its cached copy. Emits finished() (and setsChanged()) once all
    // have answered, at most the transfer limit after this call plus the
    // time to read what came.
    void refresh();
    bool isRefreshing() const { return m_pending > 0; }

    QList<ElementSet> sets() const;
    // The sets the index-th source holds now, as it gave them.
    QList<ElementSet> setsFrom(qsizetype index) const { return m_sets.value(index); }
    QList<ElementSetSourceStatus> status() const { return m_status; }
    QString cacheFile(const QUrl &url) const { return elementSetCacheFile(m_cacheDirectory, url); }

signals:
    void loaded();
    void finished();
    // After loaded() or finished(): sets() and status() are new.
    void setsChanged();

private:
    enum class Step { Load, Refresh };
    void startDownload(int index);
    void startJob(int index, Step step, std::function<SourceUpdate()> job);
    void apply(int index, quint64 sequence, const SourceUpdate &update);
    void stepDone(Step step);

    QString m_cacheDirectory;
    QList<QUrl> m_urls;
    QList<ElementSetSourceStatus> m_status;
    QList<QList<ElementSet>> m_sets;
    QList<quint64> m_appliedSequence; // the newest job each source shows
    QList<BoundedDownload *> m_downloads;
    QNetworkAccessManager *m_network = nullptr;
    DownloadLimits m_limits{kMaxElementSetBytes, kElementSetSilenceMs, kElementSetTransferMs};
    quint64 m_generation = 0; // bumped by setUrls: older jobs are dropped
    quint64 m_sequence = 0;   // every job's number, in the order started
    int m_pending = 0;
    int m_loading = 0;
};

// The epoch of the newest set (a Julian date), none for no sets: how current
// a source is, as a group file holds sets of many ages.
std::optional<double> newestEpochJulian(const QList<ElementSet> &sets);

} // namespace slew::sky
