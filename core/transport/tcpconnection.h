// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One accepted TCP connection, served straight from its descriptor.
//
// For a server with many clients that each ask a little, often (trackers
// asking a rotctld server for the position ten times a second), QTcpSocket
// costs more than the answers: it asks the kernel how much there is before
// every read, copies it into its own buffer and goes through its socket
// engine's notifiers, and on the peer's end of input it closes outright,
// dropping the answers still to go out (endofinput.h). Measured with
// bench_idle, a bare Qt server answering every line from a QTcpSocket took
// a third more CPU per answer than the same one reading the descriptor.
//
// The descriptor is watched in a DescriptorSet shared with the server's
// other clients, so that the event loop polls one descriptor for all of
// them. read() takes what the kernel holds, write() hands the kernel what
// it takes now and keeps the rest until the peer reads it, finish() closes
// once everything has left (or after a linger, for a peer that never
// reads), abort() closes at once. What the owner calls may close the
// connection on the spot (a reset, a finish with nothing left to send):
// isOpen() says so, and no signal follows. closed() is only for what
// happens later, by itself. From its own signals it is deleted later
// (deleteLater), as any QObject.

#include "descriptorset.h"

#include <QByteArray>
#include <QByteArrayView>
#include <QHostAddress>
#include <QObject>
#include <QPointer>
#include <QTimer>

namespace slew::transport {

class TcpConnection : public QObject {
    Q_OBJECT
public:
    // Takes the descriptor (a connected TCP socket), makes it non-blocking
    // and watches it in `watcher`, shared with the server's other clients.
    TcpConnection(int descriptor, DescriptorSet *watcher, QObject *parent = nullptr);
    ~TcpConnection() override; // closes, without a signal

    bool isOpen() const { return m_fd >= 0; }
    QHostAddress peerAddress() const { return m_peerAddress; }
    quint16 peerPort() const { return m_peerPort; }
    // Small writes leave at once (TCP_NODELAY): a question and its answer
    // gain nothing from being held back to fill a segment.
    void setNoDelay(bool on);

    // Up to `size` bytes of what has come: how many, 0 when nothing has.
    // After the peer's last byte it reads 0 and atEnd() holds. A reset or
    // another failure closes the connection (isOpen() is false).
    qint64 read(char *into, qint64 size);
    bool atEnd() const { return m_atEnd; }

    // Sends what the kernel takes now; the rest waits here and leaves as
    // the peer reads. A failure (the peer reset) closes the connection.
    void write(QByteArrayView bytes);
    qint64 bytesToWrite() const { return m_pending.size() - m_pendingFrom; }

    // Reads no more and closes gracefully once everything written has left,
    // or after lingerMs for a peer that does not read it.
    void finish(int lingerMs);
    void abort();

signals:
    // Something to read, or the peer's end of input (level-triggered: said
    // again while it is not read). Not after finish() or the end of input.
    void readable();
    // Closed by itself: everything left after finish(), the linger ran out,
    // or sending the rest failed.
    void closed();

private:
    // Sends from `bytes` until done or the kernel takes no more: how much,
    // -1 on a failure.
    qint64 sendNow(QByteArrayView bytes);
    void onWritable();
    void closeDescriptor();
    // Done writing: our end of the stream, then the descriptor.
    void closeGracefully();

    // Reading until finish(), writing while something waits.
    void watch();

    int m_fd = -1;
    bool m_atEnd = false;
    bool m_finishing = false;
    QHostAddress m_peerAddress;
    quint16 m_peerPort = 0;
    QPointer<DescriptorSet> m_watcher;
    quint64 m_key = 0;
    QByteArray m_pending;
    qsizetype m_pendingFrom = 0; // what of m_pending has left
    QTimer m_linger;
};

} // namespace slew::transport
