#pragma once
// A rotator controller behind a TCP socket (serial-to-network adapters,
// ESP32 controllers, slew-sim --listen).

#include "link.h"

#include <QTcpSocket>

namespace slew::transport {

class TcpLink : public Link {
    Q_OBJECT
public:
    TcpLink(const QString &uri, QString host, quint16 port, QObject *parent = nullptr);

    QIODevice *device() override { return &m_socket; }
    void open() override;
    void close() override;
    bool isOpen() const override { return m_socket.state() == QAbstractSocket::ConnectedState; }

private:
    void onError(QAbstractSocket::SocketError error);
    void onDisconnected();

    QString m_host;
    quint16 m_port;
    QTcpSocket m_socket;
    bool m_wasConnected = false;
};

} // namespace slew::transport
