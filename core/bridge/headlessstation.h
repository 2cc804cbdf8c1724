// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Slew as a station service, with no window: a session to the rotator that
// reconnects after a loss, a rotctld-compatible server for the trackers, and
// a log line on stdout for everything that happens. On SIGINT or SIGTERM it
// stops the rotator before it exits.
//
// A controller with several rotors on one line (the Micro-2g) is served as
// several stations in one: a session and a rotctld port per rotor, all on
// the one link (transport/sharedline.h), so a tracker per antenna can steer.

#include "model/rotatorprofile.h"
#include "sky/station.h"
#include "tracking/passrunner.h"

#include <QHostAddress>
#include <QList>
#include <QObject>

#include <cstdio>
#include <memory>
#include <vector>
#include <optional>

namespace slew::session {
class RotatorSession;
}
namespace slew::transport {
class SharedLine;
}

namespace slew::bridge {

class RotctldServer;

struct HeadlessConfig {
    model::RotatorProfile profile;     // its uri is the link to open
    QHostAddress rotctldAddress = QHostAddress(QHostAddress::LocalHost);
    quint16 rotctldPort = 0;
    bool rotctldEnabled = false;
    QList<QHostAddress> allowedClients; // empty: any
    int rotctldMaxClients = 32;         // RotctldServer::kDefaultMaxClients
    std::optional<sky::Station> station; // --qth / `qth =`: where the antenna stands
    // --rotors: the rotors of a multi-rotor controller to serve, each with a
    // session and a rotctld port of its own: rotctldPort, the next port, and
    // so on (each a free port of its own when rotctldPort is 0). Empty: the
    // one rotor the URI names, or the controller's default.
    QList<int> rotors;
    // --track: follow every pass of a satellite, the sun or the moon with
    // the (first) rotor until SIGTERM. Needs the station.
    struct Track {
        tracking::TrackTarget target;
        double minElevationDeg = 0;
        std::optional<double> clockStartJulian; // --clock-start: a rehearsal
        double clockRate = 1.0;                 // --clock-rate
    };
    std::optional<Track> track;
};

// "AZMIN:AZMAX,ELMIN:ELMAX" (`--limits 0:450,0:180`) as limits, checked;
// nothing (and why in *error) otherwise.
std::optional<model::RotatorLimits> parseLimits(const QString &text, QString *error);

// "1,2,4" or "1-4" as rotor numbers 1..4, each once, in the order given;
// nothing (and why in *error) for anything else.
std::optional<QList<int>> parseRotorList(const QString &text, QString *error);

class HeadlessStation : public QObject {
    Q_OBJECT
public:
    explicit HeadlessStation(std::FILE *logFile = stdout, QObject *parent = nullptr);
    ~HeadlessStation() override;

    // Opens the link and the server; false with a message if the server
    // cannot listen (a rotator that is not there yet is retried instead).
    bool start(const HeadlessConfig &config, QString *error);

    // Stops the rotator, lets the stop leave the link, then emits finished().
    void shutdown(const QString &why);

    // The first rotor's session and server (the only ones without --rotors).
    session::RotatorSession *session() const { return m_rotors.empty() ? nullptr : m_rotors.front().session.get(); }
    RotctldServer *server() const { return m_rotors.empty() ? nullptr : m_rotors.front().server.get(); }
    tracking::PassRunner *passRunner() const { return m_runner.get(); }
    int rotorCount() const { return int(m_rotors.size()); }

signals:
    void finished();

private:
    struct Rotor {
        int number = 0; // 0: the one rotor of an ordinary rotator
        std::unique_ptr<session::RotatorSession> session;
        std::unique_ptr<RotctldServer> server;
    };
    void log(const QString &line);
    Rotor &addRotor(int number, const model::RotatorProfile &profile);
    bool listen(Rotor &rotor, const HeadlessConfig &config, quint16 port, QString *error);

    std::FILE *m_log;
    std::unique_ptr<transport::SharedLine> m_line; // with --rotors: the one link they share
    std::vector<Rotor> m_rotors;
    std::unique_ptr<tracking::StationClock> m_clock;
    std::unique_ptr<tracking::PassRunner> m_runner;
    int m_stillStopping = 0;
    bool m_stopping = false;
};

} // namespace slew::bridge
