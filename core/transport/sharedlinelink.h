#pragma once
// The link a session gets to one rotor on a SharedLine (sharedline.h): it
// looks like any other link, and its bytes go by way of the shared line.

#include "link.h"

#include <QByteArray>
#include <QIODevice>
#include <QPointer>

namespace slew::transport {

class SharedLine;
class SharedLineLink;

// The session's end of one rotor's share of the line.
class SharedLineDevice : public QIODevice {
public:
    explicit SharedLineDevice(SharedLineLink *link) : m_link(link) {}

    bool isSequential() const override { return true; }
    qint64 bytesAvailable() const override { return m_received.size() + QIODevice::bytesAvailable(); }
    // What the line has still to send, this rotor's or not: a stop before
    // exit waits for it all (session/stopbeforeexit.h).
    qint64 bytesToWrite() const override;

    // Bytes from the line for this rotor; false if the session has left
    // more than kMaxUnread unread, and they were dropped.
    bool deliver(const QByteArray &bytes);
    static constexpr qint64 kMaxUnread = 64 * 1024;

protected:
    qint64 readData(char *data, qint64 maxSize) override;
    qint64 writeData(const char *data, qint64 size) override;

private:
    SharedLineLink *m_link;
    QByteArray m_received;
};

class SharedLineLink : public Link {
    Q_OBJECT
public:
    SharedLineLink(const QString &uri, int rotor, SharedLine *line, QObject *parent = nullptr);
    ~SharedLineLink() override;

    QIODevice *device() override { return &m_device; }
    void open() override;
    void close() override;
    bool isOpen() const override { return m_open; }
    LinkHints hints() const override;
    std::optional<double> clockSeconds() const override;
    bool clockIsStepped() const override;
    bool setTimeScale(double scale) override;
    double timeScale() const override;
    void setAwaitingReply(bool awaiting) override;

    int rotor() const { return m_rotor; }
    // The line this link is a share of; null once that is gone.
    SharedLine *sharedLine() const { return m_line; }

private:
    friend class SharedLine;
    friend class SharedLineDevice;
    void send(const QByteArray &bytes);
    // Called by the line.
    void lineOpened();
    void lineDown(const QString &reason, bool opening);
    void lineGone();
    bool deliver(const QByteArray &bytes) { return m_device.deliver(bytes); }

    int m_rotor;
    QPointer<SharedLine> m_line;
    SharedLineDevice m_device;
    bool m_open = false;
    bool m_nextWriteIsQuery = false;
};

} // namespace slew::transport
