// SPDX-License-Identifier: GPL-3.0-or-later
#include "simulatorscheme.h"

#include "simulatorlink.h"
#include "simulatoroptions.h"

#include "transport/linkfactory.h"

#include <QUrlQuery>

#include <algorithm>
#include <optional>

namespace slew::sim {

namespace {

// The options a sim: URI sets; an error names the URI and the item.
std::optional<SimulatorOptions> optionsOf(const QUrl &url, const QString &uri, QString *error)
{
    SimulatorOptions options;
    const QUrlQuery query(url);
    auto items = query.queryItems(QUrl::FullyDecoded);
    // A model is a starting point that the other items adjust, wherever it stands.
    std::stable_partition(items.begin(), items.end(),
                          [](const auto &item) { return item.first.compare(u"model", Qt::CaseInsensitive) == 0; });
    for (const auto &[name, value] : items) {
        if (const QString e = applySimulatorOption(options, name, value); !e.isEmpty()) {
            *error = QStringLiteral("%1: %2").arg(uri, e);
            return std::nullopt;
        }
    }
    return options;
}

} // namespace

void registerSimulatorScheme()
{
    transport::registerLinkScheme(QStringLiteral("sim"), [](const QUrl &url, const QString &uri) {
        transport::LinkResult result;
        if (const auto options = optionsOf(url, uri, &result.error))
            result.link = std::make_unique<SimulatorLink>(uri, *options);
        return result;
    });
}

model::RotatorProfile profileForSimulator(model::RotatorProfile profile, const QString &uri)
{
    const QUrl url(uri.trimmed());
    if (url.scheme().toLower() != QLatin1String("sim"))
        return profile;
    QString error;
    const auto options = optionsOf(url, uri, &error);
    if (!options)
        return profile; // connecting will report the bad item
    // Only what the URI names: the simulator's defaults (elevation to 180)
    // are wider than a usual profile, and a tighter profile is the safe side.
    const QUrlQuery query(url);
    const RotatorConfig &r = options->rotator;
    if (query.hasQueryItem(QStringLiteral("az_max")))
        profile.limits.azMax = r.azimuth.maxDegrees;
    if (query.hasQueryItem(QStringLiteral("el_max")))
        profile.limits.elMax = r.elevation.maxDegrees;
    if (query.hasQueryItem(QStringLiteral("park_az")))
        profile.parkAz = r.parkAzimuth;
    if (query.hasQueryItem(QStringLiteral("park_el")))
        profile.parkEl = r.parkElevation;
    profile.dialect = options->dialect; // what the simulator speaks, named or not
    return profile;
}

Simulator *simulatorBehind(transport::Link *link)
{
    auto *sim = qobject_cast<SimulatorLink *>(link);
    return sim ? &sim->simulator() : nullptr;
}

} // namespace slew::sim
