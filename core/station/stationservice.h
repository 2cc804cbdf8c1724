// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Slew as a station service, with no window: a Station (station.h) built
// from the service's options, its rotctld servers listening, and a log line
// on stdout for everything that happens (stationlog.h). Its sessions
// reconnect after a loss. On SIGINT or SIGTERM it stops every rotor before
// it exits.
//
// A controller with several rotors on one line (the Micro-2g) is served as
// several stations in one: a session and a rotctld port per rotor, all on
// the one link (transport/sharedline.h), so a tracker per antenna can steer.

#include "serviceconfig.h"

#include <QObject>

#include <cstdio>
#include <memory>

namespace slew::session {
class RotatorSession;
}
namespace slew::bridge {
class RotctldServer;
}
namespace slew::tracking {
class PassRunner;
}

namespace slew::station {

class Station;
class StationLog;

class StationService : public QObject {
    Q_OBJECT
public:
    explicit StationService(std::FILE *logFile = stdout, QObject *parent = nullptr);
    ~StationService() override;

    // Builds the station, opens its servers and its links; false with a
    // message if a server cannot listen (a rotator that is not there yet is
    // retried instead).
    bool start(const ServiceConfig &config, QString *error);

    // Stops every rotor, lets the stops leave the link, then emits finished().
    void shutdown(const QString &why);

    Station *station() const { return m_station.get(); }
    // The first rotor's session and server (the only ones without --rotors).
    session::RotatorSession *session() const;
    bridge::RotctldServer *server() const;
    tracking::PassRunner *passRunner() const;
    int rotorCount() const;

signals:
    void finished();

private:
    bool listen(int index, const ServiceConfig &config, quint16 port, QString *error);
    bool startRadio(const ServiceConfig &config, QString *error);
    bool openPassRecords(const ServiceConfig &config, QString *error);

    std::FILE *m_logFile;
    std::unique_ptr<Station> m_station;
    std::unique_ptr<StationLog> m_log;
    bool m_tracking = false; // --track: targets are the tracker's, logged as its plan
};

} // namespace slew::station
