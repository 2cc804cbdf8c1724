// SPDX-License-Identifier: GPL-3.0-or-later
#include "site.h"

#include "input/finitenumber.h"
#include "input/logtext.h"

#include <QStringList>

#include <algorithm>
#include <cmath>

namespace slew::sky {
namespace {

// Each pair of characters divides the previous cell: fields of 20°×10°
// (letters A–R), squares of 2°×1° (digits), subsquares of 5′×2.5′ (letters
// A–X) and extended squares of 30″×15″ (digits).
struct LocatorLevel {
    QChar first;
    int count;
    double lonSize;
    double latSize;
};

constexpr double kSubsquareLon = 2.0 / 24.0;
constexpr double kSubsquareLat = 1.0 / 24.0;

const LocatorLevel kLevels[] = {
    {u'A', 18, 20.0, 10.0},
    {u'0', 10, 2.0, 1.0},
    {u'A', 24, kSubsquareLon, kSubsquareLat},
    {u'0', 10, kSubsquareLon / 10.0, kSubsquareLat / 10.0},
};

} // namespace

bool locatorToSite(const QString &text, Site *out, QString *error)
{
    const QString locator = text.trimmed();
    if (locator.size() != 4 && locator.size() != 6 && locator.size() != 8) {
        *error = QStringLiteral("a Maidenhead locator has 4, 6 or 8 characters (JO65, JO65hq, JO65hq42), \"%1\" has %2")
                     .arg(input::loggableText(locator, 80))
                     .arg(locator.size());
        return false;
    }
    double lon = -180.0, lat = -90.0;
    double lonSize = 0, latSize = 0;
    for (int level = 0; level < locator.size() / 2; ++level) {
        const LocatorLevel &l = kLevels[level];
        const int lonIndex = locator[2 * level].toUpper().unicode() - l.first.unicode();
        const int latIndex = locator[2 * level + 1].toUpper().unicode() - l.first.unicode();
        if (lonIndex < 0 || lonIndex >= l.count || latIndex < 0 || latIndex >= l.count) {
            const QString allowed = level % 2 == 0
                                        ? QStringLiteral("letters %1 to %2").arg(l.first).arg(QChar(l.first.unicode() + l.count - 1))
                                        : QStringLiteral("digits");
            *error = QStringLiteral("locator \"%1\": characters %2 and %3 must be %4")
                         .arg(input::loggableText(locator, 80))
                         .arg(2 * level + 1)
                         .arg(2 * level + 2)
                         .arg(allowed);
            return false;
        }
        lon += lonIndex * l.lonSize;
        lat += latIndex * l.latSize;
        lonSize = l.lonSize;
        latSize = l.latSize;
    }
    Site s;
    s.longitudeDeg = lon + lonSize / 2.0;
    s.latitudeDeg = lat + latSize / 2.0;
    s.locator = locator.left(2).toUpper() + locator.mid(2, 2) + locator.mid(4, 2).toLower() + locator.mid(6);
    *out = s;
    return true;
}

QString siteLocator(double latitudeDeg, double longitudeDeg)
{
    double lon = std::clamp(longitudeDeg + 180.0, 0.0, 359.999999);
    double lat = std::clamp(latitudeDeg + 90.0, 0.0, 179.999999);
    QString result;
    for (int level = 0; level < 3; ++level) {
        const LocatorLevel &l = kLevels[level];
        const int lonIndex = int(lon / l.lonSize);
        const int latIndex = int(lat / l.latSize);
        QChar first = level == 2 ? QChar(u'a') : l.first;
        result += QChar(first.unicode() + lonIndex);
        result += QChar(first.unicode() + latIndex);
        lon -= lonIndex * l.lonSize;
        lat -= latIndex * l.latSize;
    }
    return result;
}

bool parseSite(const QString &text, Site *out, QString *error)
{
    const QString t = text.trimmed();
    if (t.isEmpty()) {
        *error = QStringLiteral("no station given: use LAT,LON[,HEIGHT_M] or a Maidenhead locator");
        return false;
    }
    if (!t.contains(u','))
        return locatorToSite(t, out, error);

    const QStringList parts = t.split(u',');
    if (parts.size() != 2 && parts.size() != 3) {
        *error = QStringLiteral("\"%1\": a station is LAT,LON or LAT,LON,HEIGHT_M").arg(input::loggableText(t, 80));
        return false;
    }
    // Finite numbers only: a site saved as "nan,0" would make every later
    // pass search loop without end.
    const std::optional<double> lat = input::finiteNumber(parts[0]);
    const std::optional<double> lon = input::finiteNumber(parts[1]);
    const std::optional<double> height = parts.size() == 3 ? input::finiteNumber(parts[2]) : std::optional<double>(0.0);
    if (!lat || !lon || !height) {
        *error = QStringLiteral("\"%1\": latitude, longitude and height must be finite numbers (degrees, degrees, "
                                "metres)")
                     .arg(input::loggableText(t, 80));
        return false;
    }
    Site s;
    s.latitudeDeg = *lat;
    s.longitudeDeg = *lon;
    s.heightM = *height;
    if (s.latitudeDeg < -90.0 || s.latitudeDeg > 90.0) {
        *error = QStringLiteral("latitude %1° is outside -90..90").arg(s.latitudeDeg);
        return false;
    }
    if (s.longitudeDeg < -180.0 || s.longitudeDeg > 360.0) {
        *error = QStringLiteral("longitude %1° is outside -180..360").arg(s.longitudeDeg);
        return false;
    }
    if (s.longitudeDeg > 180.0)
        s.longitudeDeg -= 360.0;
    if (s.heightM < -500.0 || s.heightM > 10000.0) {
        *error = QStringLiteral("height %1 m is outside -500..10000 m above the ellipsoid").arg(s.heightM);
        return false;
    }
    *out = s;
    return true;
}

QString describeSite(const Site &s)
{
    return QStringLiteral("%1° %2, %3° %4, %5 m above the ellipsoid — locator %6")
        .arg(std::fabs(s.latitudeDeg), 0, 'f', 4)
        .arg(s.latitudeDeg >= 0 ? QStringLiteral("N") : QStringLiteral("S"))
        .arg(std::fabs(s.longitudeDeg), 0, 'f', 4)
        .arg(s.longitudeDeg >= 0 ? QStringLiteral("E") : QStringLiteral("W"))
        .arg(s.heightM, 0, 'f', 0)
        .arg(siteLocator(s.latitudeDeg, s.longitudeDeg));
}

} // namespace slew::sky
