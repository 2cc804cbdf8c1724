#include "loopbackpipe.h"

#include <QMetaMethod>

#include <algorithm>
#include <cstring>

namespace slew::sim {

void PipeEnd::close()
{
    m_buffer.clear();
    QIODevice::close();
    if (m_peer && m_peer->isOpen())
        QMetaObject::invokeMethod(m_peer, &QIODevice::readChannelFinished, Qt::QueuedConnection);
}

qint64 PipeEnd::readData(char *data, qint64 maxSize)
{
    const qint64 n = std::min<qint64>(maxSize, m_buffer.size());
    if (n > 0) {
        std::memcpy(data, m_buffer.constData(), size_t(n));
        m_buffer.remove(0, n);
    }
    return n;
}

qint64 PipeEnd::writeData(const char *data, qint64 size)
{
    if (m_peer && m_peer->isOpen())
        m_peer->accept(data, size);
    // bytesWritten only for a listener: each report is an event posted to
    // the loop, and every poll of the simulator would post two for nobody.
    static const QMetaMethod bytesWrittenSignal = QMetaMethod::fromSignal(&QIODevice::bytesWritten);
    if (isSignalConnected(bytesWrittenSignal)) {
        m_unreportedWritten += size;
        notify();
    }
    return size;
}

void PipeEnd::accept(const char *data, qint64 size)
{
    const qint64 room = std::max<qint64>(0, maxBuffered - m_buffer.size());
    m_buffer.append(data, std::min(size, room));
    notify();
}

void PipeEnd::notify()
{
    if (m_notifyQueued)
        return;
    m_notifyQueued = true;
    QMetaObject::invokeMethod(
        this,
        [this] {
            m_notifyQueued = false;
            if (const qint64 written = std::exchange(m_unreportedWritten, 0); written > 0)
                emit bytesWritten(written);
            if (!m_buffer.isEmpty())
                emit readyRead();
        },
        Qt::QueuedConnection);
}

LoopbackPipe::LoopbackPipe(QObject *parent) : QObject(parent)
{
    m_host.connectTo(&m_device);
    m_device.connectTo(&m_host);
}

} // namespace slew::sim
