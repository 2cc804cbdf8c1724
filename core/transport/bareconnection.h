// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// An accepted TCP connection as its bare descriptor, for a server that
// serves it without Qt's sockets: the rotctld server hands each one to a
// thread of its own that blocks in read() on it (bridge/rotctldclient.h).
//
// The object is what BoundedTcpServer counts a client by, until it is
// destroyed: the server that takes the descriptor keeps the object for as
// long as it serves the client. Destroyed with the descriptor still in it,
// it closes it.

#include <QHostAddress>
#include <QObject>

namespace slew::transport {

class BareConnection : public QObject {
    Q_OBJECT
public:
    // Takes the descriptor (a connected TCP socket).
    explicit BareConnection(int descriptor, QObject *parent = nullptr);
    ~BareConnection() override;

    bool holdsDescriptor() const { return m_fd >= 0; }
    QHostAddress peerAddress() const { return m_peerAddress; }
    quint16 peerPort() const { return m_peerPort; }
    // Small writes leave at once (TCP_NODELAY): a question and its answer
    // gain nothing from being held back to fill a segment.
    void setNoDelay(bool on);

    // Hands the descriptor over; the caller closes it. -1 once taken.
    int takeDescriptor();
    // Closes it now (a client refused).
    void abort();

private:
    int m_fd = -1;
    QHostAddress m_peerAddress;
    quint16 m_peerPort = 0;
};

} // namespace slew::transport
