// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Answering a TCP client that has finished sending (shutdown(SHUT_WR),
// `nc -N`, `socat -t`) before it has read its answers.
//
// Qt closes a socket outright when it reads the end of input, and with it
// the answers still to be written. A server that wants to answer what such
// a client sent last keeps a second descriptor for the connection
// (SpareSocketHandle): the connection stays open on it after Qt lets go, the
// last answers leave through it, and the server closes it when done.

#include <QByteArrayView>
#include <QtGlobal>

class QAbstractSocket;

namespace slew::transport {

// True when the peer's end of input is next in line: nothing is buffered
// on our side or in the kernel, and the peer has shut down its sending side.
bool peerFinishedSending(const QAbstractSocket &socket);

class SpareSocketHandle {
public:
    // A duplicate of the socket's descriptor (invalid if it has none).
    explicit SpareSocketHandle(const QAbstractSocket &socket);
    ~SpareSocketHandle();
    SpareSocketHandle(const SpareSocketHandle &) = delete;
    SpareSocketHandle &operator=(const SpareSocketHandle &) = delete;

    bool isValid() const { return m_fd >= 0; }
    // The peer ended its sending cleanly (FIN, not reset) and the
    // connection still takes what we write: its last words may be answered.
    bool peerAwaitsAnswers() const;
    // Writes what the kernel takes now, without blocking; returns how much.
    qint64 send(QByteArrayView bytes);
    // Sends the end of our output, then lets the descriptor go.
    void close();

private:
    int m_fd = -1;
};

} // namespace slew::transport
