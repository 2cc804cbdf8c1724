// SPDX-License-Identifier: GPL-3.0-or-later
#include "transponderwatch.h"

#include "transpondersources.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>

namespace slew::radio {

TransponderWatch::TransponderWatch(TransponderSources *sources, QObject *parent)
    : QObject(parent), m_sources(sources)
{
    m_settle.setSingleShot(true);
    m_settle.setInterval(kSettleMs);
    connect(&m_settle, &QTimer::timeout, this, &TransponderWatch::onSettled);
    connect(&m_watcher, &QFileSystemWatcher::directoryChanged, &m_settle, qOverload<>(&QTimer::start));
    // Whatever this Slew read last is what the copies are compared with.
    auto noteRead = [this] {
        m_read = stamps();
        watchFolders(); // a new source's copy may sit in a folder new too
    };
    connect(m_sources, &TransponderSources::transpondersChanged, this, noteRead);
    noteRead();
}

QList<TransponderWatch::CopyStamp> TransponderWatch::stamps() const
{
    QList<CopyStamp> out;
    for (const QUrl &url : m_sources->urls()) {
        const QFileInfo copy(m_sources->cacheFile(url));
        out << (copy.exists() ? CopyStamp{copy.lastModified(), copy.size()} : CopyStamp{});
    }
    return out;
}

void TransponderWatch::watchFolders()
{
    QStringList folders{QFileInfo(QSettings().fileName()).absolutePath(), transponderCacheDirectory()};
    for (const QUrl &url : m_sources->urls())
        folders << QFileInfo(m_sources->cacheFile(url)).absolutePath();
    for (const QString &folder : std::as_const(folders)) {
        // Made if missing: a folder not there yet cannot be watched, and the
        // first copy would land unseen.
        if (!m_watcher.directories().contains(folder) && QDir().mkpath(folder))
            m_watcher.addPath(folder);
    }
}

void TransponderWatch::onSettled()
{
    if (m_sources->isBusy()) {
        m_settle.start(); // this Slew's own load or refresh first
        return;
    }
    QSettings().sync(); // what another process wrote since, read again
    const QList<QUrl> saved = savedTransponderUrls();
    if (!saved.isEmpty() && saved != m_sources->urls()) {
        m_sources->setUrls(saved);
        m_sources->loadFromCache();
        emit followed(tr("the list saved by another Slew is read: %n source(s)", nullptr, int(saved.size())));
        return;
    }
    if (stamps() != m_read) {
        m_sources->loadFromCache();
        emit followed(tr("copies refreshed by another Slew are read"));
    }
}

} // namespace slew::radio
