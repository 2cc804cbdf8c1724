// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The element sets a command-line mode names satellites from (--passes,
// --where, --schedule, --track, --export-elements, a station's remote
// `track`): the file --tle gives, in any of the five forms, or else the
// cached copies of the sources the window keeps (Sky → Element sets…,
// refreshed by slew --update-elements), so the command line sees the same
// satellites the window does. The caller is told where they came from and
// which entries were skipped, and says so.

#include "sharedoptions.h"

#include "sky/elementset.h"

#include <QList>
#include <QString>
#include <QStringList>

#include <optional>

class QCommandLineParser;

namespace slew::cli {

struct ElementSetOption {
    QList<sky::ElementSet> sets;
    // "amateur.csv: 74 sets (CSV)", or "the cached copy of URL: 74 sets
    // (CSV), downloaded 2026-12-01T10:00:00Z": for "element sets from …".
    QString origin;
    // Entries that could not be read, each "FILE:LINE: skipped: why".
    QStringList skipped;
    bool fromCache = false;
};

// --tle FILE when given; otherwise the cache. Nothing, and *error, when the
// file cannot be read, or when there is neither --tle nor a cached set.
std::optional<ElementSetOption> readElementSetOption(const QCommandLineParser &parser, const OptionLabel &label,
                                                     QString *error);

// The cached copies alone: what the window starts with.
ElementSetOption cachedElementSets();

} // namespace slew::cli
