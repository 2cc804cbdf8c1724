#pragma once
// The master side of a pseudo-terminal as a QIODevice, non-blocking, driven
// by socket notifiers: readyRead when the peer wrote, writes queued until the
// terminal takes them. QFile cannot do this (it never signals readyRead).

#include <QByteArray>
#include <QIODevice>
#include <QSocketNotifier>

#include <memory>

namespace slew::sim {

class PtyMasterDevice : public QIODevice {
    Q_OBJECT
public:
    // Takes ownership of fd, which must be non-blocking.
    explicit PtyMasterDevice(int fd, QObject *parent = nullptr);
    ~PtyMasterDevice() override;

    bool isSequential() const override { return true; }
    qint64 bytesAvailable() const override { return m_readBuffer.size() + QIODevice::bytesAvailable(); }
    qint64 bytesToWrite() const override { return m_writeBuffer.size(); }
    void close() override;

    static constexpr qsizetype maxBuffered = 256 * 1024;

protected:
    qint64 readData(char *data, qint64 maxSize) override;
    qint64 writeData(const char *data, qint64 size) override;

private:
    void readFromFd();
    void writeToFd();

    int m_fd;
    std::unique_ptr<QSocketNotifier> m_readNotifier;
    std::unique_ptr<QSocketNotifier> m_writeNotifier;
    QByteArray m_readBuffer;
    QByteArray m_writeBuffer;
};

} // namespace slew::sim
