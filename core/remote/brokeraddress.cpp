// SPDX-License-Identifier: GPL-3.0-or-later
#include "brokeraddress.h"

#include "input/logtext.h"

#include <QHostAddress>
#include <QUrl>
#include <QUrlQuery>

namespace slew::remote {
namespace {

QString shown(const QString &text)
{
    return input::loggableText(text, 80);
}

bool printable(const QString &text)
{
    for (const QChar c : text) {
        if (c.unicode() < 0x20 || c.unicode() == 0x7f)
            return false;
    }
    return true;
}

} // namespace

QString BrokerAddress::display() const
{
    QString host = this->host;
    if (host.contains(u':'))
        host = QStringLiteral("[%1]").arg(host); // an IPv6 address
    return QStringLiteral("%1://%2%3:%4")
        .arg(tls ? QStringLiteral("mqtts") : QStringLiteral("mqtt"),
             user.isEmpty() ? QString() : user + u'@', host)
        .arg(port);
}

bool isLoopbackHost(const QString &host)
{
    if (host.compare(QLatin1String("localhost"), Qt::CaseInsensitive) == 0)
        return true;
    const QHostAddress address(host);
    return !address.isNull() && address.isLoopback();
}

QString checkStationName(const QString &name)
{
    if (name.isEmpty())
        return QStringLiteral("a station's name may not be empty");
    if (name.size() > kLongestStationName)
        return QStringLiteral("a station's name is at most %1 characters, not %2").arg(kLongestStationName).arg(name.size());
    for (const QChar c : name) {
        const bool ok = (c >= u'a' && c <= u'z') || (c >= u'A' && c <= u'Z') || (c >= u'0' && c <= u'9') || c == u'-'
                        || c == u'_' || c == u'.';
        if (!ok)
            return QStringLiteral("'%1' has '%2' in it: a station's name is letters, digits, '-', '_' and '.' "
                                  "(MQTT reads '/', '+' and '#' as levels and wildcards)")
                .arg(shown(name), shown(QString(c)));
    }
    return {};
}

std::optional<BrokerAddress> parseBrokerAddress(const QString &text, QString *error)
{
    const QString trimmed = text.trimmed();
    const QUrl url(trimmed, QUrl::StrictMode);
    const QString scheme = url.scheme().toLower();
    if (!url.isValid() || (scheme != u"mqtt" && scheme != u"mqtts")) {
        *error = QStringLiteral("'%1' is not a broker's address: write mqtts://USER@HOST:8883 (or mqtt://USER@localhost "
                                "for a broker on this machine)")
                     .arg(shown(trimmed));
        return std::nullopt;
    }
    BrokerAddress address;
    address.tls = scheme == u"mqtts";
    if (!url.password().isEmpty()) {
        *error = QStringLiteral("%1: no password in the address (it would show in the process list and the shell's "
                                "history): put it in a file named by --mqtt-password-file, or in SLEW_MQTT_PASSWORD")
                     .arg(shown(url.toString(QUrl::RemovePassword)));
        return std::nullopt;
    }
    address.user = url.userName(QUrl::FullyDecoded);
    if (!printable(address.user) || address.user.size() > 128) {
        *error = QStringLiteral("the user name in '%1' is not one a broker takes").arg(shown(trimmed));
        return std::nullopt;
    }
    address.host = url.host(QUrl::FullyDecoded);
    if (address.host.isEmpty()) {
        *error = QStringLiteral("'%1' names no broker host").arg(shown(trimmed));
        return std::nullopt;
    }
    const int port = url.port(address.tls ? kMqttsPort : kMqttPort);
    if (port < 1 || port > 65535) {
        *error = QStringLiteral("'%1': the port must be from 1 to 65535").arg(shown(trimmed));
        return std::nullopt;
    }
    address.port = quint16(port);
    if (!address.tls && !isLoopbackHost(address.host)) {
        *error = QStringLiteral("%1: plain mqtt:// would send the password and every command in the clear; it is "
                                "allowed only to a broker on this machine (127.0.0.1, ::1, localhost). Use "
                                "mqtts://%2%3:8883 with ?cafile=")
                     .arg(shown(address.display()), address.user.isEmpty() ? QString() : address.user + u'@',
                          address.host);
        return std::nullopt;
    }
    QString path = url.path(QUrl::FullyDecoded);
    if (path.startsWith(u'/'))
        path.remove(0, 1);
    if (path.endsWith(u'/'))
        path.chop(1);
    if (!path.isEmpty()) {
        if (const QString why = checkStationName(path); !why.isEmpty()) {
            *error = QStringLiteral("%1: %2").arg(shown(trimmed), why);
            return std::nullopt;
        }
        address.stationName = path;
    }
    const QUrlQuery query(url);
    for (const auto &[key, value] : query.queryItems(QUrl::FullyDecoded)) {
        if (key != u"cafile") {
            *error = QStringLiteral("%1: unknown setting '%2' (a broker's address takes only ?cafile=PATH)")
                         .arg(shown(address.display()), shown(key));
            return std::nullopt;
        }
        if (!address.tls) {
            *error = QStringLiteral("%1: cafile= goes with mqtts://, which checks the broker's certificate")
                         .arg(shown(address.display()));
            return std::nullopt;
        }
        if (value.isEmpty() || !printable(value)) {
            *error = QStringLiteral("%1: cafile= names no file").arg(shown(address.display()));
            return std::nullopt;
        }
        address.caFile = value;
    }
    return address;
}

} // namespace slew::remote
