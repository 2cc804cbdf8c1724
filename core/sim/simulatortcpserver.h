// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Serves a Simulator over TCP: several clients at once (32 unless told
// otherwise), each with a connection (and firmware) of its own, all moving
// the same rotator. One client too many reads `ALbusy:…` (in the dialects
// that send alarms) and is closed; a host that shuts down its sending side
// still gets the answers to what it sent.

#include "simulatorconnection.h"

#include "transport/boundedtcpserver.h"

#include <QHostAddress>
#include <QObject>

class QTcpSocket;

namespace slew::sim {

class Simulator;

class SimulatorTcpServer : public QObject {
    Q_OBJECT
public:
    static constexpr int kDefaultMaxClients = transport::BoundedTcpServer::kDefaultMaxClients;

    SimulatorTcpServer(Simulator &simulator, const ConnectionSettings &settings, QObject *parent = nullptr);

    // Port 0 picks a free port; serverPort() then tells which.
    bool listen(const QHostAddress &address, quint16 port);
    QString errorString() const { return m_server.errorString(); }
    QHostAddress serverAddress() const { return m_server.serverAddress(); }
    quint16 serverPort() const { return m_server.serverPort(); }
    int clientCount() const { return m_clients; }
    void setMaxClients(int count);
    int maxClients() const { return m_server.maxClients(); }

signals:
    void clientCountChanged(int count);
    // For the operator: out of descriptors, clients refused.
    void notice(const QString &text);

private:
    void accept(QTcpSocket *socket);

    Simulator &m_simulator;
    ConnectionSettings m_settings;
    transport::BoundedTcpServer m_server;
    int m_clients = 0;
};

} // namespace slew::sim
