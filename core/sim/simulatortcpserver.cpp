#include "simulatortcpserver.h"

#include <QTcpSocket>

namespace slew::sim {

SimulatorTcpServer::SimulatorTcpServer(Simulator &simulator, const ConnectionSettings &settings, QObject *parent)
    : QObject(parent), m_simulator(simulator), m_settings(settings)
{
    connect(&m_server, &QTcpServer::newConnection, this, &SimulatorTcpServer::accept);
}

bool SimulatorTcpServer::listen(const QHostAddress &address, quint16 port)
{
    return m_server.listen(address, port);
}

void SimulatorTcpServer::accept()
{
    while (QTcpSocket *socket = m_server.nextPendingConnection()) {
        // Small replies should leave at once, not wait for more to coalesce.
        socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        auto *connection = new SimulatorConnection(m_simulator, socket, m_settings, socket);
        connect(connection, &SimulatorConnection::dropRequested, socket, &QTcpSocket::abort, Qt::QueuedConnection);
        connect(socket, &QTcpSocket::disconnected, this, [this, socket] {
            socket->deleteLater();
            emit clientCountChanged(--m_clients);
        });
        emit clientCountChanged(++m_clients);
    }
}

} // namespace slew::sim
