// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundedtcpserver.h"

#include "bareconnection.h"

#include <QSocketNotifier>
#include <QTcpSocket>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstring>
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

namespace slew::transport {

namespace {
// A refused client that does not read its line is cut off after this.
constexpr int kRefusalLingerMs = 2000;
// Accepts per wake-up, so a burst of connections cannot starve the rest.
constexpr int kAcceptsPerWake = 64;

// The process' descriptor limit, or INT_MAX when there is none.
int descriptorLimit()
{
    rlimit limit{};
    if (::getrlimit(RLIMIT_NOFILE, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY || limit.rlim_cur > INT_MAX)
        return INT_MAX;
    return int(limit.rlim_cur);
}

// The descriptor the next open or accept would get: the kernel hands out the
// lowest free number, so every number below it is in use. -1 when there is
// none left at all.
int lowestFreeDescriptor(int anyOpen)
{
    const int probe = ::fcntl(anyOpen, F_DUPFD_CLOEXEC, 0);
    if (probe >= 0)
        ::close(probe);
    return probe;
}
} // namespace

BoundedTcpServer::BoundedTcpServer(QObject *parent) : QObject(parent)
{
    m_retry.setSingleShot(true);
    m_retry.setInterval(kRetryAcceptMs);
    connect(&m_retry, &QTimer::timeout, this, &BoundedTcpServer::resumeAccepting);
}

BoundedTcpServer::~BoundedTcpServer()
{
    close();
}

bool BoundedTcpServer::listen(const QHostAddress &address, quint16 port)
{
    close();
    if (!m_server.listen(address, port))
        return false;
    m_server.pauseAccepting(); // Qt's own accepting stays off: see the header
    m_incoming = std::make_unique<QSocketNotifier>(m_server.socketDescriptor(), QSocketNotifier::Read);
    connect(m_incoming.get(), &QSocketNotifier::activated, this, &BoundedTcpServer::acceptPending);
    return true;
}

void BoundedTcpServer::close()
{
    m_retry.stop();
    m_waitingForDescriptors = false;
    m_incoming.reset();
    m_server.close();
}

void BoundedTcpServer::setMaxClients(int count)
{
    m_maxClients = std::max(1, count);
}

void BoundedTcpServer::setReservedDescriptors(int count)
{
    m_reserved = std::max(0, count);
}

bool BoundedTcpServer::descriptorsLow(int lowestFree) const
{
    // With the lowest free number at n, at most limit - n are left.
    const int limit = descriptorLimit();
    return lowestFree < 0 || (limit != INT_MAX && lowestFree >= limit - m_reserved);
}

void BoundedTcpServer::acceptPending()
{
    if (!m_incoming || !m_incoming->isEnabled()) // closed, or paused since this was queued
        return;
    const int listener = int(m_server.socketDescriptor());
    for (int i = 0; i < kAcceptsPerWake; ++i) {
        const int fd = ::accept4(listener, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
        if (fd < 0) {
            switch (errno) {
            case EINTR:
            case ECONNABORTED: // the client gave up while waiting: the next one
            case EPROTO:
                continue;
            case EAGAIN:
#if EAGAIN != EWOULDBLOCK
            case EWOULDBLOCK:
#endif
                // Nobody left waiting. Said once the queue has drained, not
                // every time one waiting client gets in.
                if (m_waitingForDescriptors) {
                    m_waitingForDescriptors = false;
                    emit notice(tr("accepting connections again"));
                }
                return;
            default:
                // EMFILE, ENFILE, ENOBUFS, ENOMEM, or worse: the connection
                // stays queued in the kernel, and trying again now fails again.
                waitForDescriptors(QString::fromLocal8Bit(std::strerror(errno)));
                return;
            }
        }
        if (m_bare && m_clients < m_maxClients) {
            auto *connection = new BareConnection(fd, this);
            count(connection);
            emit connectionArrived(connection);
        } else {
            // A refused client is told why through Qt in either case.
            auto *socket = new QTcpSocket(this);
            if (!socket->setSocketDescriptor(fd)) {
                ::close(fd);
                delete socket;
                continue;
            }
            if (m_clients >= m_maxClients) {
                refuse(socket);
            } else {
                count(socket);
                emit clientArrived(socket);
            }
        }
        // This one is served, but the next would eat into the reserve.
        if (m_reserved > 0 && descriptorsLow(lowestFreeDescriptor(listener))) {
            waitForDescriptors(tr("%1 descriptors kept for the rest of the process").arg(m_reserved));
            return;
        }
    }
}

void BoundedTcpServer::count(QObject *client)
{
    ++m_clients;
    connect(client, &QObject::destroyed, this, [this] {
        --m_clients;
        m_refusedSinceNotice = 0;
        // A descriptor came free: try the waiting clients now.
        if (m_waitingForDescriptors)
            resumeAccepting();
    });
}

void BoundedTcpServer::refuse(QTcpSocket *socket)
{
    // One notice until a client leaves, not one per refused client.
    if (m_refusedSinceNotice++ == 0)
        emit notice(tr("refused a client from %1: already %2 clients, the most allowed")
                        .arg(socket->peerAddress().toString())
                        .arg(m_maxClients));
    connect(socket, &QTcpSocket::disconnected, socket, &QObject::deleteLater);
    QTimer::singleShot(kRefusalLingerMs, socket, [socket] {
        socket->abort();
        socket->deleteLater();
    });
    if (!m_refusal.isEmpty())
        socket->write(m_refusal);
    socket->disconnectFromHost(); // after the line has left
}

void BoundedTcpServer::waitForDescriptors(const QString &why)
{
    m_incoming->setEnabled(false);
    if (!m_waitingForDescriptors) {
        m_waitingForDescriptors = true;
        emit notice(tr("cannot accept a connection with %1 clients (%2): new connections wait")
                        .arg(m_clients)
                        .arg(why));
    }
    m_retry.start();
}

void BoundedTcpServer::resumeAccepting()
{
    m_retry.stop();
    if (!m_incoming)
        return;
    ++m_acceptRetries;
    // Still low: keep waiting, without taking one more client into the
    // reserve on every retry.
    if (m_reserved > 0 && descriptorsLow(lowestFreeDescriptor(int(m_server.socketDescriptor())))) {
        m_retry.start();
        return;
    }
    m_incoming->setEnabled(true);
    // Look now rather than when the next client knocks, so that a drained
    // queue is noticed (and said) even if nobody else comes.
    QMetaObject::invokeMethod(this, &BoundedTcpServer::acceptPending, Qt::QueuedConnection);
}

} // namespace slew::transport
