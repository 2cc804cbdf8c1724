// SPDX-License-Identifier: GPL-3.0-or-later
#include "simulatortcpserver.h"

#include "transport/endofinput.h"

#include <QTcpSocket>
#include <QTimer>

#include <memory>

namespace slew::sim {

namespace {
constexpr qint64 kReadChunk = 16 * 1024;
constexpr int kCloseLingerMs = 5000; // a host that stopped sending and never reads
} // namespace

SimulatorTcpServer::SimulatorTcpServer(Simulator &simulator, const ConnectionSettings &settings, QObject *parent)
    : QObject(parent), m_simulator(simulator), m_settings(settings)
{
    setMaxClients(kDefaultMaxClients);
    connect(&m_server, &transport::BoundedTcpServer::clientArrived, this, &SimulatorTcpServer::accept);
    connect(&m_server, &transport::BoundedTcpServer::notice, this, &SimulatorTcpServer::notice);
}

bool SimulatorTcpServer::listen(const QHostAddress &address, quint16 port)
{
    return m_server.listen(address, port);
}

void SimulatorTcpServer::setMaxClients(int count)
{
    m_server.setMaxClients(count);
    const bool alarms = m_settings.dialect == protocol::Dialect::Easycomm2
                        || m_settings.dialect == protocol::Dialect::Easycomm3;
    m_server.setRefusal(alarms ? "ALbusy:max-clients=" + QByteArray::number(m_server.maxClients()) + '\n'
                               : QByteArray());
}

void SimulatorTcpServer::accept(QTcpSocket *socket)
{
    // Small replies should leave at once, not wait for more to coalesce.
    socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
    // Qt reads no further ahead than the connection handles in one go, so
    // it cannot see the host's end of input before its last lines.
    socket->setReadBufferSize(kReadChunk);
    auto spare = std::make_shared<transport::SpareSocketHandle>(*socket);
    auto *connection = new SimulatorConnection(m_simulator, socket, m_settings, socket);
    connect(connection, &SimulatorConnection::dropRequested, socket, &QTcpSocket::abort, Qt::QueuedConnection);
    auto finished = std::make_shared<bool>(false);
    // Connected after the connection's own readyRead handler, so this sees
    // what is left once it has read.
    connect(socket, &QTcpSocket::readyRead, this, [socket, connection, finished] {
        if (*finished || !transport::peerFinishedSending(*socket))
            return;
        *finished = true;
        socket->write(connection->takeFinalOutput());
        QTimer::singleShot(kCloseLingerMs, socket, [socket] { socket->abort(); });
        socket->disconnectFromHost(); // once the answers have left
    });
    connect(socket, &QTcpSocket::disconnected, this, [this, socket, connection, spare, finished] {
        // Qt saw the end of input first and closed: the answers to the
        // host's last lines leave through the spare descriptor.
        if (!*finished && spare->peerAwaitsAnswers()) {
            *finished = true;
            spare->send(connection->takeFinalOutput(socket->readAll()));
        }
        spare->close();
        socket->deleteLater();
        emit clientCountChanged(--m_clients);
    });
    emit clientCountChanged(++m_clients);
}

} // namespace slew::sim
