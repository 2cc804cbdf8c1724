// SPDX-License-Identifier: GPL-3.0-or-later
#include "tcpconnection.h"

#include <cerrno>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

namespace slew::transport {

TcpConnection::TcpConnection(int descriptor, DescriptorSet *watcher, QObject *parent)
    : QObject(parent), m_fd(descriptor), m_watcher(watcher)
{
    if (m_fd < 0)
        return;
    ::fcntl(m_fd, F_SETFL, ::fcntl(m_fd, F_GETFL) | O_NONBLOCK);
    sockaddr_storage peer{};
    socklen_t length = sizeof peer;
    if (::getpeername(m_fd, reinterpret_cast<sockaddr *>(&peer), &length) == 0) {
        m_peerAddress = QHostAddress(reinterpret_cast<const sockaddr *>(&peer));
        if (peer.ss_family == AF_INET)
            m_peerPort = ntohs(reinterpret_cast<const sockaddr_in *>(&peer)->sin_port);
        else if (peer.ss_family == AF_INET6)
            m_peerPort = ntohs(reinterpret_cast<const sockaddr_in6 *>(&peer)->sin6_port);
    }
    if (m_watcher) {
        m_key = m_watcher->add(m_fd, DescriptorSet::Readable, [this](int events) {
            if (events & DescriptorSet::Readable)
                emit readable();
            if (events & DescriptorSet::Writable)
                onWritable();
        });
    }
    if (m_key == 0) // nothing would ever say it can be read
        closeDescriptor();
    m_linger.setSingleShot(true);
    connect(&m_linger, &QTimer::timeout, this, [this] {
        closeDescriptor();
        emit closed();
    });
}

TcpConnection::~TcpConnection()
{
    closeDescriptor();
}

void TcpConnection::setNoDelay(bool on)
{
    const int value = on ? 1 : 0;
    if (m_fd >= 0)
        ::setsockopt(m_fd, IPPROTO_TCP, TCP_NODELAY, &value, sizeof value);
}

qint64 TcpConnection::read(char *into, qint64 size)
{
    while (m_fd >= 0 && !m_atEnd && size > 0) {
        const ssize_t n = ::recv(m_fd, into, size_t(size), MSG_DONTWAIT);
        if (n > 0)
            return n;
        if (n == 0) {
            m_atEnd = true;
            watch(); // the end stays readable: said once is enough
            break;
        }
        if (errno == EINTR)
            continue;
        if (errno != EAGAIN && errno != EWOULDBLOCK)
            closeDescriptor(); // reset, or worse: nobody to answer
        break;
    }
    return 0;
}

void TcpConnection::write(QByteArrayView bytes)
{
    if (m_fd < 0 || bytes.isEmpty())
        return;
    qint64 sent = 0;
    // Behind what already waits, or the bytes would leave out of order.
    if (bytesToWrite() == 0) {
        sent = sendNow(bytes);
        if (sent < 0) {
            closeDescriptor();
            return;
        }
    }
    if (sent < bytes.size()) {
        m_pending.append(bytes.sliced(sent));
        watch();
    }
}

void TcpConnection::finish(int lingerMs)
{
    if (m_fd < 0)
        return;
    m_finishing = true;
    watch();
    if (bytesToWrite() == 0) {
        closeGracefully();
        return;
    }
    m_linger.start(lingerMs);
}

void TcpConnection::abort()
{
    closeDescriptor();
}

qint64 TcpConnection::sendNow(QByteArrayView bytes)
{
    qint64 sent = 0;
    while (sent < bytes.size()) {
        const ssize_t n = ::send(m_fd, bytes.data() + sent, size_t(bytes.size() - sent), MSG_DONTWAIT | MSG_NOSIGNAL);
        if (n > 0) {
            sent += n;
        } else if (n < 0 && errno == EINTR) {
            continue;
        } else if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
            break;
        } else {
            return -1;
        }
    }
    return sent;
}

void TcpConnection::watch()
{
    if (m_watcher && m_key != 0)
        m_watcher->watch(m_key, (m_finishing || m_atEnd ? 0 : DescriptorSet::Readable)
                                    | (bytesToWrite() > 0 ? DescriptorSet::Writable : 0));
}

void TcpConnection::onWritable()
{
    if (m_fd < 0) // closed by what it read this turn
        return;
    const qint64 sent = sendNow(QByteArrayView(m_pending).sliced(m_pendingFrom));
    if (sent < 0) {
        closeDescriptor();
        emit closed();
        return;
    }
    m_pendingFrom += sent;
    if (bytesToWrite() > 0) {
        // What has left goes once it is most of the buffer: a peer that
        // reads as fast as it is written to would keep it all otherwise.
        if (m_pendingFrom > m_pending.size() / 2) {
            m_pending.remove(0, m_pendingFrom);
            m_pendingFrom = 0;
        }
        return;
    }
    m_pending.clear();
    m_pendingFrom = 0;
    watch();
    if (m_finishing) {
        closeGracefully();
        emit closed();
    }
}

void TcpConnection::closeGracefully()
{
    // Our end of the stream first: the peer reads everything, then its end.
    ::shutdown(m_fd, SHUT_WR);
    closeDescriptor();
}

void TcpConnection::closeDescriptor()
{
    if (m_fd < 0)
        return;
    m_linger.stop();
    if (m_watcher)
        m_watcher->remove(m_key);
    m_key = 0;
    ::close(m_fd);
    m_fd = -1;
    m_pending.clear();
    m_pendingFrom = 0;
}

} // namespace slew::transport
