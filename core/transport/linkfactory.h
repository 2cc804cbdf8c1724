#pragma once
// Making a Link from a URI.
//
//   serial:/dev/ttyUSB0?baud=19200&data=8&parity=none&stop=1&flow=none
//   tcp://host:port
//   ...?checksum=1                      (serial, tcp and sim: every line framed `*HH`)
//   sim:?kp=..&az_max=450...            (core/sim registers this scheme)
//   rotctld://host:port                 (core/bridge registers this scheme)
//
// Schemes other than serial and tcp are registered at start-up by the module
// that owns them, so the transport layer does not depend on the simulator.

#include "link.h"

#include <QString>
#include <QUrl>

#include <functional>
#include <memory>

namespace slew::transport {

struct LinkResult {
    std::unique_ptr<Link> link; // null on error
    QString error;              // names the URI and the cause
};

using LinkMaker = std::function<LinkResult(const QUrl &url, const QString &uri)>;

// Parses the URI and builds the link, unopened. A malformed URI, an unknown
// scheme or a bad query item gives an error and no link.
LinkResult createLink(const QString &uri);

// Adds a scheme ("sim", "rotctld"). A later registration replaces an earlier one.
void registerLinkScheme(const QString &scheme, LinkMaker maker);

bool isSchemeRegistered(const QString &scheme);

// What the link a URI makes says of its far end (link.h), without opening
// it; nothing for a URI that makes no link.
LinkHints linkHintsFor(const QString &uri);

} // namespace slew::transport
