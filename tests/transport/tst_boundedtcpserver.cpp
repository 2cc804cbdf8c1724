// transport::BoundedTcpServer against the real kernel, in this process: the
// descriptor limit (RLIMIT_NOFILE) is lowered around each case, so that
// running low and running out are met for real, not simulated.
//
// - Running low: accepting pauses while the next client would eat into the
//   reserve, the reserve stays free, and the waiting clients get in as served
//   ones leave.
// - Running out (what the reserve exists to prevent, caused here by the test
//   itself taking every descriptor): accept() fails with EMFILE, accepting
//   pauses without spinning, and resumes once descriptors come free.

#include "transport/boundedtcpserver.h"
#include "transport/bareconnection.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTcpSocket>
#include <QTest>

#include <algorithm>
#include <fcntl.h>
#include <memory>
#include <sys/resource.h>
#include <unistd.h>
#include <vector>

using slew::transport::BoundedTcpServer;

namespace {

int lowestFreeDescriptor()
{
    const int probe = ::fcntl(0, F_DUPFD_CLOEXEC, 0);
    if (probe >= 0)
        ::close(probe);
    return probe;
}

double cpuSecondsOfThisProcess()
{
    rusage usage{};
    ::getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec)
        + double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e6;
}

// Lowers the soft descriptor limit for one case and puts it back after.
class DescriptorLimit {
public:
    explicit DescriptorLimit(int soft)
    {
        ::getrlimit(RLIMIT_NOFILE, &m_saved);
        rlimit lowered = m_saved;
        lowered.rlim_cur = rlim_t(soft);
        m_ok = ::setrlimit(RLIMIT_NOFILE, &lowered) == 0;
    }
    ~DescriptorLimit() { ::setrlimit(RLIMIT_NOFILE, &m_saved); }
    bool ok() const { return m_ok; }

private:
    rlimit m_saved{};
    bool m_ok = false;
};

bool noticesContain(const QSignalSpy &notices, const QString &text)
{
    for (const QList<QVariant> &args : notices) {
        if (args.at(0).toString().contains(text))
            return true;
    }
    return false;
}

} // namespace

class BoundedTcpServerTest : public QObject {
    Q_OBJECT
private slots:
    void pausesBeforeTheReserveAndLetsTheWaitingIn();
    void runningOutPausesWithoutSpinningAndResumes();
    void clientLimitRefusesPolitely();
    void bareConnectionsAreCountedAndLimitedAlike();
};

void BoundedTcpServerTest::pausesBeforeTheReserveAndLetsTheWaitingIn()
{
    constexpr int kClients = 20;
    constexpr int kReserve = 16;
    // Room for the listener, the clients' own ends, and a few served ones.
    const int limit = lowestFreeDescriptor() + 1 + kClients + 3 + kReserve;
    DescriptorLimit lowered(limit);
    QVERIFY(lowered.ok());

    BoundedTcpServer server;
    server.setMaxClients(1000);
    server.setReservedDescriptors(kReserve);
    QSignalSpy notices(&server, &BoundedTcpServer::notice);
    std::vector<QTcpSocket *> served;
    connect(&server, &BoundedTcpServer::clientArrived, this, [&](QTcpSocket *s) { served.push_back(s); });
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));

    std::vector<std::unique_ptr<QTcpSocket>> clients;
    for (int i = 0; i < kClients; ++i) {
        clients.push_back(std::make_unique<QTcpSocket>());
        clients.back()->connectToHost(QHostAddress::LocalHost, server.serverPort());
    }
    QTRY_VERIFY(server.isWaitingForDescriptors());
    QVERIFY(noticesContain(notices, QStringLiteral("new connections wait")));
    QVERIFY2(noticesContain(notices, QStringLiteral("16 descriptors kept")), qPrintable(notices.last().at(0).toString()));
    const size_t firstBatch = served.size();
    QVERIFY2(firstBatch >= 1 && firstBatch < size_t(kClients), qPrintable(QString::number(firstBatch)));
    // The reserve is intact.
    QVERIFY2(lowestFreeDescriptor() >= 0 && lowestFreeDescriptor() <= limit - kReserve,
             qPrintable(QStringLiteral("lowest free %1, limit %2").arg(lowestFreeDescriptor()).arg(limit)));

    // Retries while still low take nobody more.
    const qint64 retriesBefore = server.acceptRetries();
    QTRY_VERIFY_WITH_TIMEOUT(server.acceptRetries() >= retriesBefore + 2, 20 * BoundedTcpServer::kRetryAcceptMs);
    QCOMPARE(served.size(), firstBatch);

    // Served clients leave one at a time; the waiting ones get in.
    size_t gone = 0;
    QTRY_VERIFY_WITH_TIMEOUT(
        [&] {
            if (gone < served.size())
                delete served[gone++];
            return served.size() == size_t(kClients);
        }(),
        20000);
    QTRY_VERIFY(noticesContain(notices, QStringLiteral("accepting connections again")));
    QVERIFY(!server.isWaitingForDescriptors());
    QCOMPARE(server.clientCount(), int(served.size() - gone));
    for (size_t i = gone; i < served.size(); ++i)
        delete served[i];
}

void BoundedTcpServerTest::runningOutPausesWithoutSpinningAndResumes()
{
    constexpr int kClients = 5;
    DescriptorLimit lowered(lowestFreeDescriptor() + 64);
    QVERIFY(lowered.ok());

    BoundedTcpServer server;
    server.setReservedDescriptors(0); // nothing held back: run out for real
    QSignalSpy notices(&server, &BoundedTcpServer::notice);
    QSignalSpy arrived(&server, &BoundedTcpServer::clientArrived);
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));

    std::vector<std::unique_ptr<QTcpSocket>> clients;
    for (int i = 0; i < kClients; ++i) {
        clients.push_back(std::make_unique<QTcpSocket>());
        clients.back()->connectToHost(QHostAddress::LocalHost, server.serverPort());
    }
    // Take every descriptor left before the server gets to accept.
    std::vector<int> taken;
    for (int fd; (fd = ::open("/dev/null", O_RDONLY | O_CLOEXEC)) >= 0;)
        taken.push_back(fd);
    QVERIFY(!taken.empty());

    QTRY_VERIFY(server.isWaitingForDescriptors());
    QCOMPARE(arrived.count(), 0);
    QVERIFY(noticesContain(notices, QStringLiteral("new connections wait")));
    // Paused, not retrying in a loop: over two retries (about 1 s), well
    // under a tenth of a core.
    const double before = cpuSecondsOfThisProcess();
    QElapsedTimer span;
    span.start();
    const qint64 retriesBefore = server.acceptRetries();
    QTRY_VERIFY_WITH_TIMEOUT(server.acceptRetries() >= retriesBefore + 2, 20 * BoundedTcpServer::kRetryAcceptMs);
    const double used = cpuSecondsOfThisProcess() - before;
    qInfo("out of descriptors for %lld ms: %.3f s of CPU, %lld retries", qint64(span.elapsed()), used,
          server.acceptRetries() - retriesBefore);
    QVERIFY2(used < 0.1 * std::max<qint64>(1000, span.elapsed()) / 1000.0, qPrintable(QString::number(used)));
    QVERIFY(server.isWaitingForDescriptors());
    QCOMPARE(notices.count(), 1); // said once, not once per retry

    for (int fd : taken)
        ::close(fd);
    QTRY_COMPARE(arrived.count(), kClients);
    QTRY_VERIFY(noticesContain(notices, QStringLiteral("accepting connections again")));
    QVERIFY(!server.isWaitingForDescriptors());
    for (const QList<QVariant> &args : arrived)
        delete args.at(0).value<QTcpSocket *>();
}

void BoundedTcpServerTest::clientLimitRefusesPolitely()
{
    BoundedTcpServer server;
    server.setMaxClients(2);
    server.setRefusal("busy\n");
    QSignalSpy notices(&server, &BoundedTcpServer::notice);
    QSignalSpy arrived(&server, &BoundedTcpServer::clientArrived);
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    std::vector<std::unique_ptr<QTcpSocket>> clients;
    for (int i = 0; i < 4; ++i) {
        clients.push_back(std::make_unique<QTcpSocket>());
        clients.back()->connectToHost(QHostAddress::LocalHost, server.serverPort());
    }
    QTRY_COMPARE(arrived.count(), 2);
    QTRY_COMPARE(clients[2]->state(), QAbstractSocket::UnconnectedState);
    QTRY_COMPARE(clients[3]->state(), QAbstractSocket::UnconnectedState);
    QCOMPARE(clients[2]->readAll(), QByteArray("busy\n"));
    QCOMPARE(clients[3]->readAll(), QByteArray("busy\n"));
    QCOMPARE(notices.count(), 1); // one notice until a client leaves
    QCOMPARE(server.clientCount(), 2);
    for (const QList<QVariant> &args : arrived)
        delete args.at(0).value<QTcpSocket *>();
    QCOMPARE(server.clientCount(), 0);
}

void BoundedTcpServerTest::bareConnectionsAreCountedAndLimitedAlike()
{
    BoundedTcpServer server;
    server.setBareConnections(true);
    server.setMaxClients(2);
    server.setRefusal("busy\n");
    QSignalSpy sockets(&server, &BoundedTcpServer::clientArrived);
    std::vector<slew::transport::BareConnection *> arrived;
    connect(&server, &BoundedTcpServer::connectionArrived, this,
            [&](slew::transport::BareConnection *c) { arrived.push_back(c); });
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    std::vector<std::unique_ptr<QTcpSocket>> clients;
    for (int i = 0; i < 4; ++i) {
        clients.push_back(std::make_unique<QTcpSocket>());
        clients.back()->connectToHost(QHostAddress::LocalHost, server.serverPort());
    }
    QTRY_COMPARE(arrived.size(), size_t(2));
    QTRY_COMPARE(clients[2]->state(), QAbstractSocket::UnconnectedState);
    QTRY_COMPARE(clients[3]->state(), QAbstractSocket::UnconnectedState);
    QCOMPARE(clients[2]->readAll(), QByteArray("busy\n"));
    QCOMPARE(clients[3]->readAll(), QByteArray("busy\n"));
    QCOMPARE(sockets.count(), 0);
    QCOMPARE(server.clientCount(), 2);
    QVERIFY(arrived[0]->holdsDescriptor());
    QCOMPARE(arrived[0]->peerPort(), clients[0]->localPort());
    for (slew::transport::BareConnection *c : arrived)
        delete c;
    QCOMPARE(server.clientCount(), 0);
    QTRY_COMPARE(clients[0]->state(), QAbstractSocket::UnconnectedState); // closed with it
}

QTEST_GUILESS_MAIN(BoundedTcpServerTest)
#include "tst_boundedtcpserver.moc"
