// SPDX-License-Identifier: GPL-3.0-or-later
#include "simulatorscheme.h"

#include "simulatorlink.h"
#include "transport/sharedline.h"
#include "transport/sharedlinelink.h"
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
        // `rotor=n` names which rotor the link drives, as on any link: a
        // hint for the session (hintsOf), not a property of the simulator.
        if (name == u"rotor") {
            const int n = value.toInt();
            if (n < 1 || n > 4) {
                *error = QStringLiteral("%1: rotor must be 1 to 4, not '%2'").arg(uri, value);
                return std::nullopt;
            }
            continue;
        }
        if (const QString e = applySimulatorOption(options, name, value); !e.isEmpty()) {
            *error = QStringLiteral("%1: %2").arg(uri, e);
            return std::nullopt;
        }
    }
    if (const QString e = checkSimulatorOptions(options); !e.isEmpty()) {
        *error = QStringLiteral("%1: %2").arg(uri, e);
        return std::nullopt;
    }
    return options;
}

// What the URI names about the simulated rotator, and the dialect it speaks
// (named or not). Only what is named: the simulator's defaults (elevation to
// 180) are wider than a usual profile, and a tighter profile is the safe side.
transport::LinkHints hintsOf(const QUrl &url, const SimulatorOptions &options)
{
    const QUrlQuery query(url);
    const RotatorConfig &r = options.rotator;
    transport::LinkHints h;
    h.dialect = protocol::dialectName(options.dialect);
    if (options.firmware != protocol::Firmware::Generic)
        h.firmware = protocol::firmwareName(options.firmware);
    h.checksum = options.checksum; // the session frames its side as the simulator does
    if (options.baud > 0)
        h.baud = options.baud; // paced as a serial line of that rate
    if (query.hasQueryItem(QStringLiteral("az_max")))
        h.azMax = r.azimuth.maxDegrees;
    if (query.hasQueryItem(QStringLiteral("el_max")))
        h.elMax = r.elevation.maxDegrees;
    if (query.hasQueryItem(QStringLiteral("park_az")))
        h.parkAz = r.parkAzimuth;
    if (query.hasQueryItem(QStringLiteral("park_el")))
        h.parkEl = r.parkElevation;
    if (query.hasQueryItem(QStringLiteral("rotor")))
        h.rotor = query.queryItemValue(QStringLiteral("rotor")).toInt();
    return h;
}

} // namespace

void registerSimulatorScheme()
{
    transport::registerLinkScheme(QStringLiteral("sim"), [](const QUrl &url, const QString &uri) {
        transport::LinkResult result;
        if (const auto options = optionsOf(url, uri, &result.error)) {
            auto link = std::make_unique<SimulatorLink>(uri, *options);
            link->setHints(hintsOf(url, *options));
            result.link = std::move(link);
        }
        return result;
    });
}

Simulator *simulatorBehind(transport::Link *link)
{
    // One rotor's share of a simulated multi-rotor line: the line's simulator.
    if (auto *shared = qobject_cast<transport::SharedLineLink *>(link))
        link = shared->sharedLine() ? shared->sharedLine()->line() : nullptr;
    auto *sim = qobject_cast<SimulatorLink *>(link);
    return sim ? &sim->simulator() : nullptr;
}

} // namespace slew::sim
