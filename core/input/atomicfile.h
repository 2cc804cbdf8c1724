// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Writing a cache or a kept file whole or not at all: a crash or a full
// disk leaves the old copy in place (QSaveFile writes beside it and renames).

#include <QByteArray>
#include <QString>

namespace slew::input {

// Writes `bytes` to `path`, making its directory when needed. Empty when
// done; otherwise why not, naming the path.
QString saveAtomically(const QString &path, const QByteArray &bytes);

} // namespace slew::input
