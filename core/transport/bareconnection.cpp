// SPDX-License-Identifier: GPL-3.0-or-later
#include "bareconnection.h"

#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

namespace slew::transport {

BareConnection::BareConnection(int descriptor, QObject *parent) : QObject(parent), m_fd(descriptor)
{
    if (m_fd < 0)
        return;
    sockaddr_storage peer{};
    socklen_t length = sizeof peer;
    if (::getpeername(m_fd, reinterpret_cast<sockaddr *>(&peer), &length) == 0) {
        m_peerAddress = QHostAddress(reinterpret_cast<const sockaddr *>(&peer));
        if (peer.ss_family == AF_INET)
            m_peerPort = ntohs(reinterpret_cast<const sockaddr_in *>(&peer)->sin_port);
        else if (peer.ss_family == AF_INET6)
            m_peerPort = ntohs(reinterpret_cast<const sockaddr_in6 *>(&peer)->sin6_port);
    }
}

BareConnection::~BareConnection()
{
    abort();
}

void BareConnection::setNoDelay(bool on)
{
    if (m_fd < 0)
        return;
    const int flag = on ? 1 : 0;
    ::setsockopt(m_fd, IPPROTO_TCP, TCP_NODELAY, &flag, sizeof flag);
}

int BareConnection::takeDescriptor()
{
    const int fd = m_fd;
    m_fd = -1;
    return fd;
}

void BareConnection::abort()
{
    if (m_fd >= 0)
        ::close(m_fd);
    m_fd = -1;
}

} // namespace slew::transport
