// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Keeps a running Slew's transponder sources (transpondersources.h) in step
// with what another Slew saved: `slew --update-transponders` writes the list
// of sources to the settings and the copies it fetched to the shared cache,
// and a window open all the while reads them as they land, not at its next
// start.
//
// It watches two folders (a file replaced atomically is a new file, which a
// watch on the old one would miss): the settings file's, and the cache's
// with those of its .trsp copies. A change is looked at once the writes
// have settled (kSettleMs): a list of sources that differs from the one in
// use is taken, and read from the cache; else copies that differ (in time
// or size) from the ones last read are read again. Its own Slew's writes
// change nothing it has not already read, so they read nothing again.
// Pure Qt Core; nothing waits.

#include <QDateTime>
#include <QFileSystemWatcher>
#include <QList>
#include <QObject>
#include <QTimer>
#include <QUrl>

namespace slew::radio {

class TransponderSources;

class TransponderWatch : public QObject {
    Q_OBJECT
public:
    // Writes settle within this: QSettings and an atomic cache write are a
    // few renames apart.
    static constexpr int kSettleMs = 300;

    // `sources` must outlive the watch.
    explicit TransponderWatch(TransponderSources *sources, QObject *parent = nullptr);

signals:
    // What was taken from another Slew, in words, for the log.
    void followed(const QString &what);

private:
    // Each source's cached copy as it stands: when written, and its size.
    struct CopyStamp {
        QDateTime modified;
        qint64 size = -1;
        bool operator==(const CopyStamp &) const = default;
    };
    QList<CopyStamp> stamps() const;
    void watchFolders();
    void onSettled();

    TransponderSources *m_sources;
    QFileSystemWatcher m_watcher;
    QTimer m_settle;
    QList<CopyStamp> m_read; // the copies as they were when last read
};

} // namespace slew::radio
