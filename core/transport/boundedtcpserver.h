// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A TCP server that stays well-behaved under pressure: at most a set number
// of clients at once (one more is told why and closed), and when the process
// runs low on file descriptors it stops accepting for a moment instead of
// retrying in a loop, and starts again as soon as a client leaves.
//
// "Low" comes before "out": accepting pauses while fewer than
// reservedDescriptors() are left under the process' limit (RLIMIT_NOFILE),
// so that clients alone can never take the descriptors the rest of the
// process needs: the rotator link reconnecting, a serial port, a log file.
// Should something else use them up all the same, accept() fails with
// EMFILE and accepting pauses the same way.
//
// QTcpServer binds and listens; accepting is done here, because Qt 6.4
// takes EMFILE from accept() for a passing condition and tries again at
// once, for as long as the connection waits: a core at 100 %.
//
// Both of Slew's servers sit on it: the rotctld bridge and slew-sim.

#include <QByteArray>
#include <QHostAddress>
#include <QObject>
#include <QTcpServer>
#include <QTimer>

#include <memory>

class QSocketNotifier;
class QTcpSocket;

namespace slew::transport {

class BareConnection;

class BoundedTcpServer : public QObject {
    Q_OBJECT
public:
    static constexpr int kDefaultMaxClients = 32;
    static constexpr int kRetryAcceptMs = 500; // after running low on descriptors
    static constexpr int kDefaultReservedDescriptors = 16;

    explicit BoundedTcpServer(QObject *parent = nullptr);
    ~BoundedTcpServer() override;

    bool listen(const QHostAddress &address, quint16 port);
    void close();
    bool isListening() const { return m_server.isListening(); }
    QString errorString() const { return m_server.errorString(); }
    QHostAddress serverAddress() const { return m_server.serverAddress(); }
    quint16 serverPort() const { return m_server.serverPort(); }

    // At least 1. Clients already connected stay when it is lowered.
    void setMaxClients(int count);
    int maxClients() const { return m_maxClients; }
    // What a client over the limit reads before it is closed (may be empty).
    void setRefusal(const QByteArray &line) { m_refusal = line; }
    // Clients handed out as bare descriptors (connectionArrived) rather
    // than QTcpSockets (clientArrived), for a server that serves them on
    // threads of its own (bareconnection.h).
    void setBareConnections(bool on) { m_bare = on; }
    bool bareConnections() const { return m_bare; }

    // Descriptors kept free for the rest of the process (at least 0).
    void setReservedDescriptors(int count);
    int reservedDescriptors() const { return m_reserved; }

    int clientCount() const { return m_clients; }
    // True while accepting is paused because descriptors ran low or out.
    bool isWaitingForDescriptors() const { return m_waitingForDescriptors; }
    // How often accepting has been retried after a pause, for diagnostics
    // and for tests that wait on retries rather than on the clock.
    qint64 acceptRetries() const { return m_acceptRetries; }

signals:
    // A client within the limit. The receiver handles it; the server counts
    // it until the socket is destroyed.
    void clientArrived(QTcpSocket *socket);
    // The same with setBareConnections(true), counted until it is destroyed.
    void connectionArrived(slew::transport::BareConnection *connection);
    // Something the operator should know, ready for a log.
    void notice(const QString &text);

private:
    void acceptPending();
    void waitForDescriptors(const QString &why);
    void resumeAccepting();
    bool descriptorsLow(int lowestFree) const;
    // Counts a client until it is destroyed.
    void count(QObject *client);
    void refuse(QTcpSocket *socket);

    QTcpServer m_server;
    std::unique_ptr<QSocketNotifier> m_incoming;
    QTimer m_retry;
    QByteArray m_refusal;
    int m_maxClients = kDefaultMaxClients;
    int m_reserved = kDefaultReservedDescriptors;
    int m_clients = 0;
    bool m_bare = false;
    bool m_waitingForDescriptors = false;
    qint64 m_refusedSinceNotice = 0;
    qint64 m_acceptRetries = 0;
};

} // namespace slew::transport
