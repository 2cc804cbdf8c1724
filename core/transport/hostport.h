#pragma once
// "127.0.0.1:4533", "[::1]:0", ":4533" — an address and port as given on a
// command line. An empty host means loopback: servers bind to 127.0.0.1
// unless the operator names another address.

#include <QHostAddress>
#include <QString>

namespace slew::transport {

bool parseHostPort(const QString &text, QHostAddress *address, quint16 *port);

} // namespace slew::transport
