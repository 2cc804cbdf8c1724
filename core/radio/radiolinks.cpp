// SPDX-License-Identifier: GPL-3.0-or-later
#include "radiolinks.h"

#include "hamlibradio.h"
#include "hamliburi.h"
#include "rigctldradio.h"

#include <QUrl>

namespace slew::radio {

namespace {

std::unique_ptr<RadioLink> refuse(QString *error, const QString &uri, const QString &why)
{
    if (error)
        *error = QObject::tr("%1: %2").arg(uri, why);
    return nullptr;
}

} // namespace

std::unique_ptr<RadioLink> makeRadioLink(const QString &uri, QString *error)
{
    const QString trimmed = uri.trimmed();
    if (trimmed.isEmpty()) {
        if (error)
            *error = QObject::tr("no radio link given (expected rigctld://host:port, hamlib:MODEL or sim:)");
        return nullptr;
    }
    const QUrl url(trimmed, QUrl::StrictMode);
    if (!url.isValid())
        return refuse(error, trimmed, QObject::tr("not a valid URI: %1").arg(url.errorString()));
    const QString scheme = url.scheme().toLower();
    if (scheme == QLatin1String("rigctld")) {
        if (url.host().isEmpty())
            return refuse(error, trimmed, QObject::tr("no host named (expected rigctld://host:port)"));
        if (!url.path().isEmpty() || url.hasQuery() || url.hasFragment())
            return refuse(error, trimmed, QObject::tr("rigctld takes no path or options (expected rigctld://host:port)"));
        const int port = url.port(RigctldRadioLink::kDefaultPort);
        if (port <= 0)
            return refuse(error, trimmed, QObject::tr("port 0 is no rigctld's port"));
        return std::make_unique<RigctldRadioLink>(trimmed, url.host(), quint16(port));
    }
    if (scheme == QLatin1String("hamlib") || scheme == QLatin1String("sim")) {
        QString why;
        std::optional<HamlibRadioConfig> config = hamlibRadioConfig(url, trimmed, &why);
        if (!config)
            return refuse(error, trimmed, why);
        return std::make_unique<HamlibRadioLink>(std::move(*config));
    }
    if (scheme.isEmpty())
        return refuse(error, trimmed, QObject::tr("no scheme (expected rigctld://host:port, hamlib:MODEL or sim:)"));
    return refuse(error, trimmed, QObject::tr("unknown radio link kind '%1' (known: rigctld, hamlib, sim)").arg(scheme));
}

} // namespace slew::radio
