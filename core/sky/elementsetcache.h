// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The steps of loading and refreshing one element-set source that touch
// files or parse text: each runs on a worker thread (ElementSetSources hands them
// to QtConcurrent) and returns what the source holds afterwards. None of
// them blocks on a path: files are read with readBoundedFile, which refuses
// devices and FIFOs and stops at the cap.

#include "elementsetsources.h"

namespace slew::sky {

struct SourceUpdate {
    ElementSetSourceStatus status;
    QList<ElementSet> sets;
};

// The cached copy alone, with no network: what Slew starts with.
SourceUpdate loadCachedSource(const QUrl &url, const QString &cacheFile);

// A new copy of the source (the downloaded answer, or a local file's
// bytes). It replaces the cached copy, which is written atomically, only
// when whyNotReplace() finds nothing against it; otherwise the cached copy
// stays and status.error says why.
SourceUpdate takeNewCopy(const QUrl &url, const QString &cacheFile, const QByteArray &text);

// A refresh that brought no new copy: the cached copy stays, and why.
SourceUpdate keepCachedCopy(const QUrl &url, const QString &cacheFile, const QString &why);

// A file:// source: the file read with the cap, then as takeNewCopy.
SourceUpdate readLocalSource(const QUrl &url, const QString &cacheFile);

} // namespace slew::sky
