// SPDX-License-Identifier: GPL-3.0-or-later
#include "targetbyname.h"

#include "station.h"

#include "sky/elementsetsources.h"

namespace slew::station {

std::optional<tracking::TrackTarget> targetByName(const Station &station, const QList<sky::ElementSet> &given,
                                                  const QString &text, QString *why)
{
    tracking::TrackTarget target;
    QString bad;
    if (const auto fixed = tracking::TrackTarget::parseFixedOrCelestial(text, &bad))
        return *fixed;
    if (!bad.isEmpty()) {
        *why = bad;
        return std::nullopt;
    }
    if (text.compare(QLatin1String("sun"), Qt::CaseInsensitive) == 0) {
        target.kind = tracking::TrackTarget::Kind::Sun;
        return target;
    }
    if (text.compare(QLatin1String("moon"), Qt::CaseInsensitive) == 0) {
        target.kind = tracking::TrackTarget::Kind::Moon;
        return target;
    }
    // The sets the station was given first, then the cache's.
    QList<sky::ElementSet> sets = given;
    for (const sky::ElementSet &cached : station.elementSets()->sets()) {
        bool known = false;
        for (const sky::ElementSet &g : given)
            known = known || g.catalogueNumber == cached.catalogueNumber;
        if (!known)
            sets.append(cached);
    }
    QString notFound;
    const sky::ElementSet *found = sky::findOneSatellite(sets, text, &notFound);
    if (!found) {
        *why = QObject::tr("%1 among the station's element sets").arg(notFound);
        return std::nullopt;
    }
    target.elements = *found;
    return target;
}

std::optional<QList<tracking::TrackTarget>> targetsByName(const Station &station, const QList<sky::ElementSet> &given,
                                                          const QStringList &texts, QString *why)
{
    QList<tracking::TrackTarget> targets;
    for (const QString &text : texts) {
        const std::optional<tracking::TrackTarget> found = targetByName(station, given, text.trimmed(), why);
        if (!found)
            return std::nullopt;
        targets.append(*found);
    }
    return targets;
}

} // namespace slew::station
