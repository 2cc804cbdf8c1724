// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where the antenna stands: geodetic latitude and longitude (WGS-84,
// degrees, east positive) and height above the ellipsoid. Operators often
// know their station by its Maidenhead locator instead; a locator stands for
// the centre of the square it names.

#include "horizonmask.h"

#include <QString>

#include <memory>

namespace slew::sky {

struct Site {
    double latitudeDeg = 0;
    double longitudeDeg = 0;
    double heightM = 0;
    QString locator; // as given, when the site came from one
    // What hides the sky here (horizonmask.h); none: a flat horizon. Every
    // pass predicted for the site rises and sets on it.
    std::shared_ptr<const HorizonMask> horizon;
};

// Where the window keeps the site (QSettings key: its name stays as saved
// settings have it), as the text typed; the command line falls back to it
// when --qth is not given.
inline constexpr char kSiteSettingsKey[] = "sky/station";
// Where the window keeps the path of the site's horizon mask file
// (horizonmask.h); the sky commands fall back to it as to the site.
inline constexpr char kHorizonSettingsKey[] = "sky/horizonFile";

// "LAT,LON", "LAT,LON,HEIGHT_M" or a 4, 6 or 8 character locator
// ("JO65", "JO65hq", "JO65hq42"). On refusal, *error says why.
bool parseSite(const QString &text, Site *out, QString *error);

// The centre of a Maidenhead square; false (and *error) for a malformed one.
bool locatorToSite(const QString &locator, Site *out, QString *error);

// The 6-character locator of a position.
QString siteLocator(double latitudeDeg, double longitudeDeg);

// "55.6875° N, 12.6250° E, 20 m above the ellipsoid — locator JO65hq",
// for the window and the station service's log.
QString describeSite(const Site &site);

} // namespace slew::sky
