// SPDX-License-Identifier: GPL-3.0-or-later
#include "utctime.h"

#include "skyvector.h"

#include <QTimeZone>

#include <cmath>

namespace slew::sky {

QDateTime utcFromJulian(double julian)
{
    return utcFromUnixMs(qint64(std::llround(unixSecondsFromJulian(julian) * 1000.0)));
}

QDateTime utcFromUnixMs(qint64 ms)
{
#if QT_VERSION >= QT_VERSION_CHECK(6, 5, 0)
    return QDateTime::fromMSecsSinceEpoch(ms, QTimeZone::UTC);
#else
    return QDateTime::fromMSecsSinceEpoch(ms, Qt::UTC);
#endif
}

QString isoUtc(double julian)
{
    return utcFromJulian(julian).toString(Qt::ISODate);
}

std::optional<double> julianFromIso(const QString &text)
{
    QDateTime t = QDateTime::fromString(text.trimmed(), Qt::ISODateWithMs);
    if (!t.isValid())
        t = QDateTime::fromString(text.trimmed(), Qt::ISODate);
    if (!t.isValid())
        return std::nullopt;
    if (t.timeSpec() == Qt::LocalTime)
        t.setTimeZone(QTimeZone::utc());
    return julianFromUnixSeconds(t.toMSecsSinceEpoch() / 1000.0);
}

double julianNow()
{
    return julianFromUnixSeconds(QDateTime::currentMSecsSinceEpoch() / 1000.0);
}

} // namespace slew::sky
