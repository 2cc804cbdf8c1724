// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The names operators call satellites by, beside the names their element
// sets carry: "AO-91" for "FOX-1B (AO-91)", "ZARYA" for "ISS (ZARYA)",
// "OSCAR7" typed without its space, and the AMSAT OSCAR numbers and former
// names of amateur satellites whose sets do not say them (satellitenames.cpp,
// a table with its source). findSatellites (elementset.h) searches by these.

#include <QString>
#include <QStringList>
#include <QStringView>

#include <optional>

namespace slew::sky {

// A name as searched: letters and digits only, upper case ("AO-91",
// "ao 91" and "AO91" are all "AO91").
QString satelliteNameKey(QStringView name);

// The keys a set's name may be named by whole: the name, the part before
// its parentheses, and each designation inside them ("FOX-1B (AO-91)":
// FOX1BAO91, FOX1B, AO91).
QStringList satelliteNameKeys(const QString &name);

// The catalogue number an AMSAT name or former name stands for ("AO7",
// "OSCAR7", "JAS2"), from the built-in table; none for any other key.
std::optional<int> amsatCatalogueNumber(const QString &key);

} // namespace slew::sky
