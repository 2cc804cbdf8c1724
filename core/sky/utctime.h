// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// UTC instants as Julian dates, to and from ISO 8601 text and QDateTime.

#include <QDateTime>
#include <QString>

#include <optional>

namespace slew::sky {

// UTC as Qt::UTC, not a time zone: ISO 8601 output then ends in "Z".
QDateTime utcFromJulian(double julian);
// The same from milliseconds since 1970 (the one place that knows how each
// Qt version says it: 6.4 has no QTimeZone::UTC, 6.8 deprecates Qt::UTC here).
QDateTime utcFromUnixMs(qint64 ms);
// "2024-06-20T12:00:00Z"
QString isoUtc(double julian);
// ISO 8601, with or without milliseconds; a time without a zone is UTC.
std::optional<double> julianFromIso(const QString &text);
// The system's UTC now.
double julianNow();

} // namespace slew::sky
