// SPDX-License-Identifier: GPL-3.0-or-later
#include "savedcalibration.h"

#include "input/finitenumber.h"

#include <QSettings>
#include <QUrl>
#include <QUrlQuery>

#include <cmath>

namespace slew::model {

namespace {

// A URI has slashes, which QSettings reads as groups: percent-encode it.
QString keyFor(const QString &uri)
{
    return QStringLiteral("calibration/") + QString::fromLatin1(QUrl::toPercentEncoding(calibrationUri(uri)));
}

} // namespace

QString calibrationUri(const QString &uri)
{
    // Only a rotor on a shared line is rewritten: other keys stay as the
    // operator typed them, as they were always saved.
    QUrl url(uri.trimmed());
    QUrlQuery query(url);
    if (!query.hasQueryItem(QStringLiteral("rotor")))
        return uri;
    const QString rotor = query.queryItemValue(QStringLiteral("rotor"));
    query.removeAllQueryItems(QStringLiteral("rotor"));
    query.addQueryItem(QStringLiteral("rotor"), rotor);
    url.setQuery(query);
    return url.toString();
}

std::optional<CalibrationOffsets> savedCalibration(const QString &uri)
{
    const QStringList parts = QSettings().value(keyFor(uri)).toStringList();
    if (parts.size() != 2)
        return std::nullopt;
    const std::optional<double> az = input::finiteNumber(parts[0]), el = input::finiteNumber(parts[1]);
    // A hand-edited settings file must not carry an offset the profile refuses.
    if (!az || !el || std::abs(*az) > 180.0 || std::abs(*el) > 20.0)
        return std::nullopt;
    return CalibrationOffsets{*az, *el};
}

void saveCalibration(const QString &uri, const CalibrationOffsets &offsets)
{
    QSettings().setValue(keyFor(uri), QStringList{QString::number(offsets.azDeg, 'f', 4),
                                                  QString::number(offsets.elDeg, 'f', 4)});
}

} // namespace slew::model
