// SPDX-License-Identifier: GPL-3.0-or-later
// The rotctld server's clients on threads of their own (bridge/rotctldclient.h):
// a position read is answered without a turn of the main thread's event
// loop, everything else waits for it and keeps its order, a lost link reads
// as RPRT -6 at once, closing the server never hangs on a client that waits
// for an answer, and position reads are said to the window at most four
// times a second, and only to a listener.
//
// The clients here are plain blocking sockets, so that the test's own thread
// (the main one) can stay out of its event loop while it asks.

#include "bridge/rotctldserver.h"
#include "linkschemes.h"
#include "session/rotatorsession.h"

#include <QDir>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

#include <cerrno>
#include <thread>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

using namespace slew;

namespace {

// A connected blocking socket to 127.0.0.1:port, or -1; with a receive
// buffer of `receiveBuffer` bytes if not 0 (before connecting, so that the
// window it offers stays that small).
int connectTo(quint16 port, int receiveBuffer = 0)
{
    const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0)
        return -1;
    if (receiveBuffer > 0)
        ::setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &receiveBuffer, sizeof receiveBuffer);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(port);
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(fd, reinterpret_cast<const sockaddr *>(&address), sizeof address) != 0) {
        ::close(fd);
        return -1;
    }
    return fd;
}

bool sendLine(int fd, const QByteArray &bytes)
{
    return ::send(fd, bytes.constData(), size_t(bytes.size()), MSG_NOSIGNAL) == bytes.size();
}

// What arrives within `timeoutMs` until `lines` lines have come, without
// turning the event loop. Fewer lines when the time runs out or the server
// closes; "<closed>" is appended for a close.
QByteArray receiveLines(int fd, int lines, int timeoutMs)
{
    QByteArray got;
    QElapsedTimer clock;
    clock.start();
    while (got.count('\n') < lines) {
        const qint64 left = timeoutMs - clock.elapsed();
        if (left <= 0)
            break;
        pollfd p{fd, POLLIN, 0};
        if (::poll(&p, 1, int(left)) <= 0)
            continue;
        char buffer[4096];
        const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
        if (n <= 0) {
            got += "<closed>";
            break;
        }
        got.append(buffer, n);
    }
    return got;
}

} // namespace

class RotctldClientTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { registerLinkSchemes(); }
    void init();
    void cleanup();

    void positionIsAnsweredWithoutTheMainLoop();
    void otherRequestsWaitForTheMainLoopInOrder();
    void aLostLinkReadsAsAnError();
    void closingNeverWaitsForAnAnswer();
    void positionReadsAreSaidAtMostFourTimesASecond();
    void aClientCostsOneDescriptor();
    void aClientThatDoesNotReadIsCutOff();

private:
    QByteArray expectedPosition() const;
    session::RotatorSession *session = nullptr;
    bridge::RotctldServer *server = nullptr;
    int client = -1;
};

void RotctldClientTest::init()
{
    session = new session::RotatorSession;
    server = new bridge::RotctldServer(session);
    model::RotatorProfile p;
    p.uri = "sim:?model=satnogs&time_scale=10";
    session->setProfile(p);
    session->connectTo(p.uri);
    QVERIFY(QTest::qWaitFor([&] { return session->isConnected() && session->hasPosition(); }, 10000));
    QString error;
    QVERIFY2(server->listen(QHostAddress::LocalHost, 0, &error), qPrintable(error));
    client = connectTo(server->port());
    QVERIFY(client >= 0);
    // Accepted on the main thread, as the listening server lives there.
    QTRY_COMPARE(server->clients().size(), 1);
}

void RotctldClientTest::cleanup()
{
    if (client >= 0)
        ::close(client);
    client = -1;
    delete server;
    server = nullptr;
    delete session;
    session = nullptr;
}

QByteArray RotctldClientTest::expectedPosition() const
{
    return QStringLiteral("%1\n%2\n").arg(session->azimuth(), 0, 'f', 2).arg(session->elevation(), 0, 'f', 2).toLatin1();
}

void RotctldClientTest::positionIsAnsweredWithoutTheMainLoop()
{
    // The main thread stays right here, out of its event loop, while the
    // client asks ten times: each answer comes from the client's thread.
    const QByteArray expected = expectedPosition();
    for (int i = 0; i < 10; ++i) {
        QVERIFY(sendLine(client, "p\n"));
        QCOMPARE(receiveLines(client, 2, 5000), expected);
    }
    // The long form too (`+\get_pos`, as the SatNOGS client may send).
    QVERIFY(sendLine(client, "+\\get_pos\n"));
    const QByteArray extended = receiveLines(client, 4, 5000);
    QVERIFY2(extended.startsWith("get_pos:\n") && extended.endsWith("RPRT 0\n"), extended.constData());
    // The Trackers tab's figures count them.
    const auto info = server->clients().value(0);
    QCOMPARE(info.commands, 11);
    QCOMPARE(info.lastCommand, QStringLiteral("+\\get_pos"));
}

void RotctldClientTest::otherRequestsWaitForTheMainLoopInOrder()
{
    // A stop is the session's business: it is not answered while the main
    // thread is away from its loop...
    QVERIFY(sendLine(client, "S\np\n"));
    QCOMPARE(receiveLines(client, 1, 300), QByteArray());
    // ...and the `p` behind it waits too: answers keep the order of questions.
    QByteArray got;
    QVERIFY(QTest::qWaitFor(
        [&] {
            got += receiveLines(client, 3 - got.count('\n'), 10);
            return got.count('\n') >= 3;
        },
        5000));
    QCOMPARE(got, "RPRT 0\n" + expectedPosition());
}

void RotctldClientTest::aLostLinkReadsAsAnError()
{
    QVERIFY(sendLine(client, "p\n"));
    QCOMPARE(receiveLines(client, 2, 5000), expectedPosition());
    // The link closes on the main thread; the next read, on the client's
    // thread, already knows: Hamlib's "input/output error".
    session->disconnectFromRotator();
    QVERIFY(sendLine(client, "p\n"));
    QCOMPARE(receiveLines(client, 1, 5000), QByteArray("RPRT -6\n"));
}

void RotctldClientTest::closingNeverWaitsForAnAnswer()
{
    // The client's thread hands `S` over and waits; the main thread never
    // gets to it, because it closes the server first.
    QVERIFY(sendLine(client, "S\n"));
    // The thread counts the line before it hands it over; the count is read
    // under the client's lock, without turning the event loop (which would
    // answer it).
    QElapsedTimer read;
    read.start();
    while (server->clients().value(0).commands < 1 && read.elapsed() < 5000)
        std::this_thread::yield();
    QCOMPARE(server->clients().value(0).commands, 1);
    QElapsedTimer clock;
    clock.start();
    delete server;
    server = nullptr;
    QVERIFY2(clock.elapsed() < 1000, qPrintable(QString::number(clock.elapsed())));
    // The client reads the end of the stream, not an answer.
    QCOMPARE(receiveLines(client, 1, 5000), QByteArray("<closed>"));
}

void RotctldClientTest::positionReadsAreSaidAtMostFourTimesASecond()
{
    QSignalSpy said(server, &bridge::RotctldServer::commandReceived);
    QElapsedTimer clock;
    clock.start();
    int asked = 0;
    while (clock.elapsed() < 1000) {
        QVERIFY(sendLine(client, "p\n"));
        QCOMPARE(receiveLines(client, 2, 5000).count('\n'), 2);
        ++asked;
        QTest::qWait(10);
    }
    QTest::qWait(300);
    QVERIFY2(asked >= 20, qPrintable(QString::number(asked)));
    // One at the first read, then at most one every 250 ms.
    QVERIFY2(said.size() >= 2 && said.size() <= 5, qPrintable(QString::number(said.size())));
    QCOMPARE(said.last().at(1).toString(), QStringLiteral("p"));
}

void RotctldClientTest::aClientCostsOneDescriptor()
{
    // Its socket, and nothing else: a thread with an event loop of its own
    // would add a wake-up descriptor each, and a server short of descriptors
    // (tst_headless) would run out twice as fast.
    auto descriptors = [] { return QDir(QStringLiteral("/proc/self/fd")).entryList(QDir::NoDotAndDotDot | QDir::System).size(); };
    const qsizetype before = descriptors();
    int more[5];
    for (int &fd : more) {
        fd = connectTo(server->port());
        QVERIFY(fd >= 0);
    }
    QTRY_COMPARE(server->clients().size(), 6);
    for (int fd : more) {
        QVERIFY(sendLine(fd, "p\n"));
        QCOMPARE(receiveLines(fd, 2, 5000).count('\n'), 2);
    }
    // Five here (the clients' ends) and five in the server.
    QCOMPARE(descriptors() - before, 10);
    for (int fd : more)
        ::close(fd);
    QTRY_COMPARE(server->clients().size(), 1);
    QTRY_COMPARE(descriptors(), before);
}

void RotctldClientTest::aClientThatDoesNotReadIsCutOff()
{
    QSignalSpy logged(server, &bridge::RotctldServer::logMessage);
    server->setSendTimeout(300); // 5 s in service
    // It asks as fast as the kernel takes its questions and reads nothing:
    // its answers fill the server's sending side, then its own receiving one.
    const int flooder = connectTo(server->port(), 4096);
    QVERIFY(flooder >= 0);
    QTRY_COMPARE(server->clients().size(), 2);
    QByteArray questions;
    for (int i = 0; i < 4096; ++i)
        questions += "p\n";
    qint64 sent = 0;
    bool othersAnswered = false;
    QElapsedTimer clock;
    clock.start();
    // Until the server cuts it off: a send fails (reset, or broken pipe).
    while (clock.elapsed() < 20000) {
        const ssize_t n = ::send(flooder, questions.constData(), size_t(questions.size()), MSG_DONTWAIT | MSG_NOSIGNAL);
        if (n > 0) {
            sent += n;
            continue;
        }
        if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK)
            break;
        if (!othersAnswered) {
            // The flooder's thread is stuck in a send: the other client is
            // answered as ever.
            QVERIFY(sendLine(client, "p\n"));
            QCOMPARE(receiveLines(client, 2, 5000).count('\n'), 2);
            othersAnswered = true;
        }
        QTest::qWait(20);
    }
    QVERIFY(othersAnswered);
    QVERIFY2(sent > 100000, qPrintable(QString::number(sent)));
    auto saidSo = [&] {
        for (const auto &args : logged) {
            if (args.at(0).toString().contains(QStringLiteral("is not reading its answers; disconnected")))
                return true;
        }
        return false;
    };
    QTRY_VERIFY(saidSo());
    QTRY_COMPARE(server->clients().size(), 1);
    ::close(flooder);
    QVERIFY(sendLine(client, "p\n"));
    QCOMPARE(receiveLines(client, 2, 5000).count('\n'), 2);
}

QTEST_GUILESS_MAIN(RotctldClientTest)
#include "tst_rotctldclient.moc"
