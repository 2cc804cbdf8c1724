#include "ptymasterdevice.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <unistd.h>

namespace slew::sim {

PtyMasterDevice::PtyMasterDevice(int fd, QObject *parent)
    : QIODevice(parent),
      m_fd(fd),
      m_readNotifier(std::make_unique<QSocketNotifier>(fd, QSocketNotifier::Read)),
      m_writeNotifier(std::make_unique<QSocketNotifier>(fd, QSocketNotifier::Write))
{
    m_writeNotifier->setEnabled(false);
    connect(m_readNotifier.get(), &QSocketNotifier::activated, this, &PtyMasterDevice::readFromFd);
    connect(m_writeNotifier.get(), &QSocketNotifier::activated, this, &PtyMasterDevice::writeToFd);
    QIODevice::open(QIODevice::ReadWrite | QIODevice::Unbuffered);
}

PtyMasterDevice::~PtyMasterDevice()
{
    close();
}

void PtyMasterDevice::close()
{
    m_readNotifier->setEnabled(false);
    m_writeNotifier->setEnabled(false);
    if (m_fd >= 0) {
        ::close(m_fd);
        m_fd = -1;
    }
    QIODevice::close();
}

void PtyMasterDevice::readFromFd()
{
    char buffer[4096];
    bool got = false;
    while (m_readBuffer.size() < maxBuffered) {
        const ssize_t n = ::read(m_fd, buffer, sizeof buffer);
        if (n > 0) {
            m_readBuffer.append(buffer, qsizetype(n));
            got = true;
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        // EAGAIN: drained. EIO: no peer has the terminal open right now; the
        // owner keeps the slave open, so this is transient.
        break;
    }
    // Stop listening while full, or the notifier would spin; reading resumes
    // once the buffer drains (readData).
    m_readNotifier->setEnabled(m_readBuffer.size() < maxBuffered);
    if (got)
        emit readyRead();
}

qint64 PtyMasterDevice::readData(char *data, qint64 maxSize)
{
    const qint64 n = std::min<qint64>(maxSize, m_readBuffer.size());
    if (n > 0) {
        std::memcpy(data, m_readBuffer.constData(), size_t(n));
        m_readBuffer.remove(0, n);
    }
    if (m_fd >= 0 && !m_readNotifier->isEnabled() && m_readBuffer.size() < maxBuffered)
        m_readNotifier->setEnabled(true);
    return n;
}

qint64 PtyMasterDevice::writeData(const char *data, qint64 size)
{
    if (m_fd < 0)
        return -1;
    // A peer that never reads fills the terminal; what does not fit is lost,
    // as on a serial line with nobody listening.
    const qint64 room = std::max<qint64>(0, maxBuffered - m_writeBuffer.size());
    m_writeBuffer.append(data, std::min(size, room));
    writeToFd();
    return size;
}

void PtyMasterDevice::writeToFd()
{
    while (!m_writeBuffer.isEmpty() && m_fd >= 0) {
        const ssize_t n = ::write(m_fd, m_writeBuffer.constData(), size_t(m_writeBuffer.size()));
        if (n > 0) {
            m_writeBuffer.remove(0, qsizetype(n));
            emit bytesWritten(n);
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        break;
    }
    m_writeNotifier->setEnabled(!m_writeBuffer.isEmpty() && m_fd >= 0);
}

} // namespace slew::sim
