#pragma once
// Serves a Simulator over TCP: any number of clients at once, each with a
// connection (and firmware) of its own, all moving the same rotator.

#include "simulatorconnection.h"

#include <QHostAddress>
#include <QObject>
#include <QTcpServer>

namespace slew::sim {

class Simulator;

class SimulatorTcpServer : public QObject {
    Q_OBJECT
public:
    SimulatorTcpServer(Simulator &simulator, const ConnectionSettings &settings, QObject *parent = nullptr);

    // Port 0 picks a free port; serverPort() then tells which.
    bool listen(const QHostAddress &address, quint16 port);
    QString errorString() const { return m_server.errorString(); }
    QHostAddress serverAddress() const { return m_server.serverAddress(); }
    quint16 serverPort() const { return m_server.serverPort(); }
    int clientCount() const { return m_clients; }

signals:
    void clientCountChanged(int count);

private:
    void accept();

    Simulator &m_simulator;
    ConnectionSettings m_settings;
    QTcpServer m_server;
    int m_clients = 0;
};

} // namespace slew::sim
