// SPDX-License-Identifier: GPL-3.0-or-later
// transport::TcpConnection on a real loopback connection: what it reads, the
// peer's end of input, a write the kernel cannot take at once, a graceful
// close once everything has left, the linger for a peer that never reads,
// and a reset.

#include "transport/tcpconnection.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QCoreApplication>
#include <QTest>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <memory>
#include <utility>

using slew::transport::DescriptorSet;
using slew::transport::TcpConnection;

namespace {

// A loopback TCP connection: our end as a TcpConnection, the peer's as a
// blocking descriptor the test drives by hand.
struct Pair {
    DescriptorSet watcher;
    std::unique_ptr<TcpConnection> ours;
    int peer = -1;
    quint16 peerPort = 0;
    ~Pair()
    {
        if (peer >= 0)
            ::close(peer);
    }
};

std::unique_ptr<Pair> connectPair()
{
    const int listener = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof a;
    if (::bind(listener, reinterpret_cast<sockaddr *>(&a), sizeof a) != 0 || ::listen(listener, 1) != 0
        || ::getsockname(listener, reinterpret_cast<sockaddr *>(&a), &length) != 0) {
        ::close(listener);
        return {};
    }
    auto pair = std::make_unique<Pair>();
    pair->peer = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (::connect(pair->peer, reinterpret_cast<sockaddr *>(&a), sizeof a) != 0) {
        ::close(listener);
        return {};
    }
    sockaddr_in local{};
    length = sizeof local;
    ::getsockname(pair->peer, reinterpret_cast<sockaddr *>(&local), &length);
    pair->peerPort = ntohs(local.sin_port);
    pair->ours = std::make_unique<TcpConnection>(::accept4(listener, nullptr, nullptr, SOCK_CLOEXEC), &pair->watcher);
    ::close(listener);
    return pair;
}

// Everything the peer reads until our end of the stream (or timeoutMs).
QByteArray readToEnd(int fd, int timeoutMs = 10000)
{
    QByteArray got;
    char buffer[65536];
    for (;;) {
        pollfd p{fd, POLLIN, 0};
        // The event loop runs between reads, so our side can send the rest.
        QCoreApplication::processEvents();
        const int ready = ::poll(&p, 1, 10);
        if (ready == 0) {
            if ((timeoutMs -= 10) <= 0)
                return got;
            continue;
        }
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n <= 0)
            return got;
        got.append(buffer, n);
    }
}

QByteArray counting(qsizetype size)
{
    QByteArray bytes(size, Qt::Uninitialized);
    for (qsizetype i = 0; i < size; ++i)
        bytes[i] = char('a' + (i * 7 + i / 4093) % 26);
    return bytes;
}

} // namespace

namespace {

// Absence is shown by turns of the event loop, not by time: a descriptor
// still readable (level-triggered) would be reported on every turn.
void turnEventLoop(int turns)
{
    for (int i = 0; i < turns; ++i)
        QCoreApplication::processEvents(QEventLoop::AllEvents);
}

} // namespace

class TcpConnectionTest : public QObject {
    Q_OBJECT
private slots:
    void readsWhatCameThenTheEnd();
    void namesThePeer();
    void keepsWhatTheKernelDoesNotTake();
    void finishClosesOnceEverythingHasLeft();
    void finishWithNothingLeftClosesAtOnce();
    void aPeerThatNeverReadsIsCutOffAfterTheLinger();
    void aResetClosesIt();
};

void TcpConnectionTest::readsWhatCameThenTheEnd()
{
    const auto pair = connectPair();
    QVERIFY(pair && pair->ours->isOpen());
    QSignalSpy readable(pair->ours.get(), &TcpConnection::readable);
    char buffer[16];
    QCOMPARE(pair->ours->read(buffer, sizeof buffer), 0); // nothing yet
    QVERIFY(!pair->ours->atEnd());
    QCOMPARE(::write(pair->peer, "p\nP 1 2\n", 8), 8);
    QVERIFY(readable.wait(5000));
    QCOMPARE(pair->ours->read(buffer, 4), 4); // no more than asked
    QCOMPARE(QByteArray(buffer, 4), QByteArray("p\nP "));
    QCOMPARE(pair->ours->read(buffer, sizeof buffer), 4);
    QCOMPARE(QByteArray(buffer, 4), QByteArray("1 2\n"));
    ::shutdown(pair->peer, SHUT_WR);
    QVERIFY(QTest::qWaitFor([&] { return pair->ours->read(buffer, sizeof buffer) == 0 && pair->ours->atEnd(); }, 5000));
    QVERIFY(pair->ours->isOpen()); // the peer still reads what we say
    readable.clear();
    turnEventLoop(50);
    QCOMPARE(readable.count(), 0); // the end is said once, not on every turn
    pair->ours->write("answer\n");
    pair->ours->finish(5000);
    QVERIFY(!pair->ours->isOpen());
    QCOMPARE(readToEnd(pair->peer), QByteArray("answer\n"));
}

void TcpConnectionTest::namesThePeer()
{
    const auto pair = connectPair();
    QVERIFY(pair);
    QCOMPARE(pair->ours->peerAddress(), QHostAddress(QHostAddress::LocalHost));
    QCOMPARE(pair->ours->peerPort(), pair->peerPort);
}

void TcpConnectionTest::keepsWhatTheKernelDoesNotTake()
{
    const auto pair = connectPair();
    QVERIFY(pair);
    // Far more than the socket buffers of both ends hold.
    const QByteArray first = counting(16 << 20), second = "and then this\n";
    pair->ours->write(first);
    QVERIFY(pair->ours->bytesToWrite() > 0);
    pair->ours->write(second); // behind the rest, not before it
    QCOMPARE(pair->ours->bytesToWrite() > qint64(second.size()), true);
    pair->ours->finish(30000);
    QSignalSpy closed(pair->ours.get(), &TcpConnection::closed);
    const QByteArray got = readToEnd(pair->peer, 30000);
    QCOMPARE(got.size(), first.size() + second.size());
    QVERIFY(got == first + second);
    QVERIFY(closed.count() == 1 || closed.wait(5000));
    QVERIFY(!pair->ours->isOpen());
}

void TcpConnectionTest::finishClosesOnceEverythingHasLeft()
{
    const auto pair = connectPair();
    QVERIFY(pair);
    const QByteArray bytes = counting(8 << 20);
    pair->ours->write(bytes);
    QVERIFY(pair->ours->bytesToWrite() > 0);
    QSignalSpy closed(pair->ours.get(), &TcpConnection::closed);
    pair->ours->finish(30000);
    QVERIFY(pair->ours->isOpen()); // until it has all left
    QVERIFY(readToEnd(pair->peer, 30000) == bytes);
    QVERIFY(closed.count() == 1 || closed.wait(5000));
    QCOMPARE(closed.count(), 1);
}

void TcpConnectionTest::finishWithNothingLeftClosesAtOnce()
{
    const auto pair = connectPair();
    QVERIFY(pair);
    QSignalSpy closed(pair->ours.get(), &TcpConnection::closed);
    pair->ours->write("bye\n");
    pair->ours->finish(5000);
    QVERIFY(!pair->ours->isOpen());
    QCOMPARE(readToEnd(pair->peer), QByteArray("bye\n"));
    turnEventLoop(50);
    QCOMPARE(closed.count(), 0); // the owner closed it: no signal
}

void TcpConnectionTest::aPeerThatNeverReadsIsCutOffAfterTheLinger()
{
    const auto pair = connectPair();
    QVERIFY(pair);
    pair->ours->write(counting(16 << 20));
    QSignalSpy closed(pair->ours.get(), &TcpConnection::closed);
    QElapsedTimer clock;
    clock.start();
    pair->ours->finish(300);
    QVERIFY(closed.wait(5000));
    QVERIFY(clock.elapsed() >= 250);
    QVERIFY(!pair->ours->isOpen());
    QCOMPARE(pair->ours->bytesToWrite(), 0);
}

void TcpConnectionTest::aResetClosesIt()
{
    const auto pair = connectPair();
    QVERIFY(pair);
    QSignalSpy readable(pair->ours.get(), &TcpConnection::readable);
    const linger abortive{1, 0};
    ::setsockopt(pair->peer, SOL_SOCKET, SO_LINGER, &abortive, sizeof abortive);
    ::close(std::exchange(pair->peer, -1)); // RST
    QVERIFY(readable.wait(5000));
    char buffer[16];
    QCOMPARE(pair->ours->read(buffer, sizeof buffer), 0);
    QVERIFY(!pair->ours->isOpen());
    pair->ours->write("nobody\n"); // harmless once closed
    pair->ours->finish(100);
}

QTEST_GUILESS_MAIN(TcpConnectionTest)
#include "tst_tcpconnection.moc"
