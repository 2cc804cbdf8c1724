// SPDX-License-Identifier: GPL-3.0-or-later
#include "endofinput.h"

#include <QAbstractSocket>

#include <cerrno>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

namespace slew::transport {

bool peerFinishedSending(const QAbstractSocket &socket)
{
    if (socket.state() != QAbstractSocket::ConnectedState || socket.bytesAvailable() > 0)
        return false;
    const qintptr fd = socket.socketDescriptor();
    if (fd < 0)
        return false;
    // A peek that reads 0 bytes without blocking is the end of input; data
    // or EAGAIN mean the peer may still send.
    char byte = 0;
    return ::recv(int(fd), &byte, 1, MSG_PEEK | MSG_DONTWAIT) == 0;
}

SpareSocketHandle::SpareSocketHandle(const QAbstractSocket &socket)
{
    const qintptr fd = socket.socketDescriptor();
    if (fd >= 0)
        m_fd = ::fcntl(int(fd), F_DUPFD_CLOEXEC, 0); // -1 when out of descriptors: then no spare
}

SpareSocketHandle::~SpareSocketHandle()
{
    close();
}

bool SpareSocketHandle::peerAwaitsAnswers() const
{
    if (m_fd < 0)
        return false;
    tcp_info info{};
    socklen_t length = sizeof info;
    if (::getsockopt(m_fd, IPPROTO_TCP, TCP_INFO, &info, &length) != 0)
        return false;
    // CLOSE_WAIT: the peer sent FIN and we have not; a reset leaves CLOSE.
    return info.tcpi_state == TCP_CLOSE_WAIT;
}

qint64 SpareSocketHandle::send(QByteArrayView bytes)
{
    qint64 sent = 0;
    while (m_fd >= 0 && sent < bytes.size()) {
        const ssize_t n = ::send(m_fd, bytes.data() + sent, size_t(bytes.size() - sent), MSG_DONTWAIT | MSG_NOSIGNAL);
        if (n > 0)
            sent += n;
        else if (n < 0 && errno == EINTR)
            continue;
        else
            break;
    }
    return sent;
}

void SpareSocketHandle::close()
{
    if (m_fd < 0)
        return;
    ::shutdown(m_fd, SHUT_WR);
    ::close(m_fd);
    m_fd = -1;
}

} // namespace slew::transport
