// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Slew as a station service, with no window: a session to the rotator that
// reconnects after a loss, a rotctld-compatible server for the trackers, and
// a log line on stdout for everything that happens. On SIGINT or SIGTERM it
// stops the rotator before it exits.

#include "model/rotatorprofile.h"
#include "sky/station.h"

#include <QHostAddress>
#include <QList>
#include <QObject>

#include <cstdio>
#include <memory>
#include <optional>

namespace slew::session {
class RotatorSession;
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
};

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

    session::RotatorSession *session() const { return m_session.get(); }
    RotctldServer *server() const { return m_server.get(); }

signals:
    void finished();

private:
    void log(const QString &line);

    std::FILE *m_log;
    std::unique_ptr<session::RotatorSession> m_session;
    std::unique_ptr<RotctldServer> m_server;
    bool m_stopping = false;
};

} // namespace slew::bridge
