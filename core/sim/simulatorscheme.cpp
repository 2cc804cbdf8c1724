#include "simulatorscheme.h"

#include "simulatorlink.h"
#include "simulatoroptions.h"

#include "transport/linkfactory.h"

#include <QUrlQuery>

namespace slew::sim {

void registerSimulatorScheme()
{
    transport::registerLinkScheme(QStringLiteral("sim"), [](const QUrl &url, const QString &uri) {
        transport::LinkResult result;
        SimulatorOptions options;
        const QUrlQuery query(url);
        for (const auto &[name, value] : query.queryItems(QUrl::FullyDecoded)) {
            if (const QString error = applySimulatorOption(options, name, value); !error.isEmpty()) {
                result.error = QStringLiteral("%1: %2").arg(uri, error);
                return result;
            }
        }
        result.link = std::make_unique<SimulatorLink>(uri, options);
        return result;
    });
}

Simulator *simulatorBehind(transport::Link *link)
{
    auto *sim = qobject_cast<SimulatorLink *>(link);
    return sim ? &sim->simulator() : nullptr;
}

} // namespace slew::sim
