#pragma once
// Two QIODevices joined back to back, in one process: what one end writes,
// the other reads. The simulator's in-process link is one of these, with the
// host on one end and the simulated controller on the other.
//
// Bytes written are readable on the other end at once, but readyRead and
// bytesWritten are signalled from the event loop, never inside write(): a
// caller that writes and then waits sees the same order of events as with a
// socket or a serial port.

#include <QByteArray>
#include <QIODevice>
#include <QPointer>

namespace slew::sim {

class PipeEnd : public QIODevice {
    Q_OBJECT
public:
    explicit PipeEnd(QObject *parent = nullptr) : QIODevice(parent) {}

    void connectTo(PipeEnd *peer) { m_peer = peer; }

    bool isSequential() const override { return true; }
    qint64 bytesAvailable() const override { return m_buffer.size() + QIODevice::bytesAvailable(); }
    void close() override;

    // A writer that never lets the reader run loses what does not fit, like
    // an overrun serial line, rather than growing without bound.
    static constexpr qsizetype maxBuffered = 4 * 1024 * 1024;

protected:
    qint64 readData(char *data, qint64 maxSize) override;
    qint64 writeData(const char *data, qint64 size) override;

private:
    void accept(const char *data, qint64 size);
    void notify();

    QPointer<PipeEnd> m_peer;
    QByteArray m_buffer;
    qint64 m_unreportedWritten = 0;
    bool m_notifyQueued = false;
};

// Owns a connected pair of ends.
class LoopbackPipe : public QObject {
    Q_OBJECT
public:
    explicit LoopbackPipe(QObject *parent = nullptr);
    PipeEnd *hostEnd() { return &m_host; }
    PipeEnd *deviceEnd() { return &m_device; }

private:
    PipeEnd m_host;
    PipeEnd m_device;
};

} // namespace slew::sim
