#include "tcplink.h"

namespace slew::transport {

TcpLink::TcpLink(const QString &uri, QString host, quint16 port, QObject *parent)
    : Link(uri, parent), m_host(std::move(host)), m_port(port)
{
    // Small command lines must leave at once, not wait for Nagle.
    m_socket.setSocketOption(QAbstractSocket::LowDelayOption, 1);
    connect(&m_socket, &QTcpSocket::connected, this, [this] {
        m_wasConnected = true;
        m_socket.setSocketOption(QAbstractSocket::LowDelayOption, 1);
        emit opened();
    });
    connect(&m_socket, &QTcpSocket::errorOccurred, this, &TcpLink::onError);
    connect(&m_socket, &QTcpSocket::disconnected, this, &TcpLink::onDisconnected);
}

void TcpLink::open()
{
    m_wasConnected = false;
    m_socket.abort();
    m_socket.connectToHost(m_host, m_port);
}

void TcpLink::close()
{
    m_wasConnected = false; // a requested close is not a loss
    m_socket.abort();
}

void TcpLink::onError(QAbstractSocket::SocketError)
{
    if (m_wasConnected)
        return; // reported by onDisconnected()
    const QString reason = tr("%1: cannot connect to %2:%3: %4").arg(uri(), m_host).arg(m_port).arg(m_socket.errorString());
    m_socket.abort();
    emit failed(reason);
}

void TcpLink::onDisconnected()
{
    if (!m_wasConnected)
        return;
    m_wasConnected = false;
    emit lost(tr("%1: connection closed by the peer (%2)").arg(uri(), m_socket.errorString()));
}

} // namespace slew::transport
