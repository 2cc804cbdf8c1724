// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/remoteopener.h"

#include "stationwindow.h"
#include "remote/stationnetworkwindow.h"

#include "remote/remotestation.h"
#include "remote/stationdirectory.h"

#include <QUuid>

namespace slew::ui {

QMainWindow *openRemoteWindow(const remote::BrokerAddress &address, const QString &password, QString *error)
{
    remote::MqttSettings settings;
    settings.broker = address;
    settings.password = password;
    // Watching needs no fixed identity; each window is a client of its own.
    settings.clientId = QStringLiteral("slew-window-%1").arg(QUuid::createUuid().toString(QUuid::Id128).left(12));
    QMainWindow *window = nullptr;
    if (!address.stationName.isEmpty()) {
        auto *station = new remote::RemoteStation(settings, address.stationName);
        window = new StationWindow(station);
        station->setParent(window);
        if (!station->open(error)) {
            delete window;
            return nullptr;
        }
    } else {
        auto *directory = new remote::StationDirectory(settings);
        settings.clientId.clear(); // each station window it opens makes its own
        window = new StationNetworkWindow(directory, settings);
        directory->setParent(window);
        if (!directory->open(error)) {
            delete window;
            return nullptr;
        }
    }
    window->setAttribute(Qt::WA_DeleteOnClose);
    window->show();
    return window;
}

} // namespace slew::ui
