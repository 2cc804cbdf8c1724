// SPDX-License-Identifier: GPL-3.0-or-later
// slew-sim as a separate process over TCP: every command and status row of
// the Easycomm III derivative, several clients at once, faults from the command line, garbage,
// and a clean stop on SIGINT / SIGTERM.
#include "slewsimprocess.h"
#include "../common/halfclose.h"

#include <QElapsedTimer>
#include <QRandomGenerator>
#include <QRegularExpression>
#include <QTest>

#include <QTimer>

#include <csignal>
#include <list>
#include <sys/resource.h>

namespace {

double numberAfter(const QByteArray &reply, const QByteArray &prefix)
{
    const qsizetype at = reply.indexOf(prefix);
    if (at < 0)
        return qQNaN();
    QByteArray rest = reply.mid(at + prefix.size());
    for (char separator : {' ', '\n'}) {
        if (const qsizetype end = rest.indexOf(separator); end >= 0)
            rest.truncate(end);
    }
    return rest.trimmed().toDouble();
}

bool near(double value, double expected, double tolerance) { return qAbs(value - expected) <= tolerance; }

} // namespace

class TestSlewSimTcp : public QObject {
    Q_OBJECT

    SlewSimProcess m_sim;
    SimClient m_client;

    // Asks until the reply satisfies the check, or ten seconds pass.
    template <typename Check>
    bool eventually(const QByteArray &query, Check check, int lines = 1)
    {
        // Each ask waits for its answer; between asks the event loop runs.
        return QTest::qWaitFor([&] { return check(m_client.ask(query, lines)); }, 10000);
    }

private slots:
    void initTestCase()
    {
        // Four times the wall clock: these check answers, not how long slews take.
        QVERIFY2(m_sim.start({"--listen", "127.0.0.1:0", "--dialect", "easycomm3", "--model", "satnogs",
                              "--time-scale", "4"}),
                 qPrintable(m_sim.error()));
        QVERIFY2(m_sim.readyLine().contains("tcp 127.0.0.1:"), qPrintable(m_sim.readyLine()));
        QVERIFY(m_sim.port() != 0);
        QVERIFY(m_client.connectTo(m_sim.port()));
    }

    void positionCommandsAndReports()
    {
        QCOMPARE(m_client.ask("AZ EL\n"), QByteArray("AZ0.00 EL0.00\n"));
        m_client.socket().write("AZ12.5 EL7.25\n");
        QCOMPARE(m_client.ask("CR10\nCR11\n", 2), QByteArray("CR10,12.50\nCR11,7.25\n"));
        QVERIFY(eventually("AZ EL\n", [](const QByteArray &r) {
            return near(numberAfter(r, "AZ"), 12.5, 0.05) && near(numberAfter(r, "EL"), 7.25, 0.05);
        }));
        QVERIFY(eventually("GS\n", [](const QByteArray &r) { return r == "GS1028\n"; }));
        const QByteArray separate = m_client.ask("AZ\nEL\n", 2);
        QVERIFY2(separate.startsWith("AZ12.") && separate.contains("\nEL7."), separate.constData());
        QVERIFY(near(numberAfter(m_client.ask("IP3\n"), "IP3,"), 12.5, 0.05));
        QVERIFY(near(numberAfter(m_client.ask("IP4\n"), "IP4,"), 7.25, 0.05));
        // One decimal works as well as two.
        m_client.socket().write("AZ13.0\n");
        QVERIFY(eventually("AZ\n", [](const QByteArray &r) { return near(numberAfter(r, "AZ"), 13.0, 0.05); }));
    }

    void velocityCommandsStopsAndHold()
    {
        m_client.socket().write("VR5000\n");
        // The drive works hardest while it accelerates; at cruise the load
        // is friction alone and may round to 0.
        QVERIFY(eventually("IP5\n", [](const QByteArray &r) { return numberAfter(r, "IP5,") > 0; }));
        QCOMPARE(m_client.ask("CR12\n"), QByteArray("CR12,5000.00\n"));
        QVERIFY(eventually("IP7\n", [](const QByteArray &r) { return near(numberAfter(r, "IP7,"), 5.0, 0.1); }));
        QCOMPARE(m_client.ask("GS\n").left(2), QByteArray("GS"));
        QCOMPARE(int(numberAfter(m_client.ask("GS\n"), "GS")) & 0xff, 2);
        // VL0 holds actively: still in the velocity servo (CR9 1), and at
        // rest, which GS reports as idle rather than moving.
        m_client.socket().write("VL0\n");
        QVERIFY(eventually("IP7\n", [](const QByteArray &r) { return near(numberAfter(r, "IP7,"), 0.0, 0.02); }));
        QVERIFY(eventually("GS\n", [](const QByteArray &r) { return (int(numberAfter(r, "GS")) & 0xff) == 1; }));
        QCOMPARE(m_client.ask("CR9\n"), QByteArray("CR9,1.00\n"));
        // SA releases: idle.
        m_client.socket().write("SA\n");
        QCOMPARE(int(numberAfter(m_client.ask("GS\n"), "GS")) & 0xff, 1);
        QCOMPARE(m_client.ask("CR9\n"), QByteArray("CR9,2.00\n"));

        m_client.socket().write("VU3000\n");
        QVERIFY(eventually("IP6\n", [](const QByteArray &r) { return numberAfter(r, "IP6,") > 0; }));
        QCOMPARE(m_client.ask("CR13\n"), QByteArray("CR13,3000.00\n"));
        QVERIFY(eventually("IP8\n", [](const QByteArray &r) { return near(numberAfter(r, "IP8,"), 3.0, 0.1); }));
        QCOMPARE(int(numberAfter(m_client.ask("GS\n"), "GS")) >> 8, 2);
        m_client.socket().write("VD3000\n");
        QVERIFY(eventually("IP8\n", [](const QByteArray &r) { return near(numberAfter(r, "IP8,"), -3.0, 0.1); }));
        QCOMPARE(m_client.ask("VD\n"), QByteArray("VD3000\n"));
        m_client.socket().write("SE\n");
        QCOMPARE(int(numberAfter(m_client.ask("GS\n"), "GS")) >> 8, 1);
        QVERIFY(eventually("IP8\n", [](const QByteArray &r) { return near(numberAfter(r, "IP8,"), 0.0, 0.02); }));
        m_client.socket().write("VL2000\n");
        QCOMPARE(m_client.ask("VL\nCR12\n", 2), QByteArray("VL2000\nCR12,-2000.00\n"));
        m_client.socket().write("SA\n");
    }

    void configRegistersReadBack()
    {
        const double values[] = {31.5, 1.25, 12.0, 28.0, 0.5, 9.75, 5.0, 4.0};
        for (int n = 1; n <= 8; ++n)
            m_client.socket().write("CW" + QByteArray::number(n) + ',' + QByteArray::number(values[n - 1]) + '\n');
        for (int n = 1; n <= 8; ++n) {
            const QByteArray reply = m_client.ask("CR" + QByteArray::number(n) + '\n');
            QVERIFY2(reply.startsWith("CR" + QByteArray::number(n) + ','), reply.constData());
            QCOMPARE(numberAfter(reply, ","), values[n - 1]);
        }
        QCOMPARE(m_client.ask("CW9,1\n"), QByteArray("ALlimit:CW9,1\n"));
        QCOMPARE(m_client.ask("CW1,-3\n"), QByteArray("ALlimit:CW1,-3\n"));
        QCOMPARE(m_client.ask("CR1\n"), QByteArray("CR1,31.500\n"));
        // Back to the defaults, so that the moves below settle as well as they should.
        m_client.socket().write("CW1,40\nCW2,2\nCW3,20\nCW4,40\nCW5,2\nCW6,20\n");
        QCOMPARE(m_client.ask("CR6\n"), QByteArray("CR6,20.000\n"));
    }

    void statusInputsAndVersion()
    {
        const QByteArray all = m_client.ask("IP0\nIP1\nIP2\nIP5\nIP6\nVE\nGE\n\\?ENC\n", 8);
        const QList<QByteArray> lines = all.split('\n');
        QVERIFY2(QRegularExpression("^IP0,\\d+\\.\\d\\d$").match(QString(lines[0])).hasMatch(), lines[0].constData());
        QVERIFY(numberAfter(lines[0], "IP0,") >= 25.0);
        QVERIFY(QRegularExpression("^IP1,[0-3]$").match(QString(lines[1])).hasMatch());
        QVERIFY(QRegularExpression("^IP2,[0-3]$").match(QString(lines[2])).hasMatch());
        QVERIFY(QRegularExpression("^IP5,\\d+$").match(QString(lines[3])).hasMatch());
        QVERIFY(QRegularExpression("^IP6,\\d+$").match(QString(lines[4])).hasMatch());
        QCOMPARE(lines[5], QByteArray("VESlewSim-1.0"));
        QCOMPARE(lines[6], QByteArray("GE1"));
        QVERIFY2(QRegularExpression("^\\\\\\?ENC-?\\d+,-?\\d+,-?\\d+,-?\\d+$").match(QString(lines[7])).hasMatch(),
                 lines[7].constData());
    }

    void parkAndReset()
    {
        m_client.socket().write("CW7,20\nCW8,3\nPARK\n");
        QVERIFY(eventually("AZ EL\n", [](const QByteArray &r) {
            return near(numberAfter(r, "AZ"), 20.0, 0.1) && near(numberAfter(r, "EL"), 3.0, 0.1);
        }));
        m_client.socket().write("RESET\n");
        QCOMPARE(m_client.ask("GS\n"), QByteArray("GS514\n")); // both axes homing: 2 | 2 << 8
        QVERIFY(eventually("AZ EL\n", [](const QByteArray &r) { return r == "AZ0.00 EL0.00\n"; }));
        QVERIFY(eventually("GS\n", [](const QByteArray &r) { return r == "GS1028\n"; }));
        QCOMPARE(m_client.ask("GE\n"), QByteArray("GE1\n"));
    }

    void refusedInputIsAlarmedAndMovesNothing()
    {
        QCOMPARE(m_client.ask("AZ361\n"), QByteArray("ALlimit:AZ361.00\n"));
        QCOMPARE(m_client.ask("EL-1\n"), QByteArray("ALlimit:EL-1.00\n"));
        QCOMPARE(m_client.ask("QQ\n"), QByteArray("ALunknown:QQ\n"));
        QCOMPARE(m_client.ask("AZ1.2.3\n"), QByteArray("ALmalformed:AZ1.2.3\n"));
        QCOMPARE(m_client.ask("AZ-0.004\n"), QByteArray("ALlimit:AZ-0.004\n"));
        QCOMPARE(m_client.ask("VL99999999999999999999\n"), QByteArray("ALmalformed:VL99999999999999999999\n"));
        QCOMPARE(m_client.ask("VL2147483648\n"), QByteArray("ALmalformed:VL2147483648\n"));
        QCOMPARE(m_client.ask("ST99:99:99:99:99:99\n"), QByteArray("ALmalformed:ST99:99:99:99:99:99\n"));
        QCOMPARE(m_client.ask("CR12\n"), QByteArray("CR12,0.00\n"));
        QCOMPARE(m_client.ask("CR10\n"), QByteArray("CR10,0.00\n"));
    }

    void severalClientsAtOnce()
    {
        SimClient a;
        SimClient b;
        QVERIFY(a.connectTo(m_sim.port()));
        QVERIFY(b.connectTo(m_sim.port()));
        a.socket().write("GE\n");
        b.socket().write("VE\n");
        QCOMPARE(b.readLines(1), QByteArray("VESlewSim-1.0\n"));
        QCOMPARE(a.readLines(1), QByteArray("GE1\n"));
        a.socket().write("CW7,33\n");
        QCOMPARE(b.ask("CR7\n"), QByteArray("CR7,33.00\n")); // one rotator behind both
        // A half line on one connection does not disturb the other.
        a.socket().write("AZ");
        QCOMPARE(b.ask("GE\n"), QByteArray("GE1\n"));
        const QByteArray joined = a.ask(" EL\n");
        QVERIFY2(QRegularExpression("^AZ-?\\d+\\.\\d\\d EL-?\\d+\\.\\d\\d\n$").match(QString(joined)).hasMatch(),
                 joined.constData());
    }

    void garbageBarrageThenAValidQuery()
    {
        SimClient c;
        QVERIFY(c.connectTo(m_sim.port()));
        QRandomGenerator rng(7);
        QByteArray junk(512 * 1024, '\0');
        for (char &ch : junk)
            ch = char(rng.bounded(256));
        c.socket().write(junk);
        c.socket().write("\nGE\n");
        // Alarms come first; the answer follows them.
        QByteArray line;
        for (int i = 0; i < 200000 && !line.startsWith("GE"); ++i) {
            line = c.readLines(1);
            if (line.isEmpty())
                break;
        }
        QCOMPARE(line, QByteArray("GE1\n"));
        QCOMPARE(m_client.ask("GE\n"), QByteArray("GE1\n"));
    }

    void halfClosedClientsGetTheirAnswers()
    {
        // `printf 'AZ EL\n' | nc -N`: the host stops sending before it reads.
        int answered = 0;
        for (int i = 0; i < 20; ++i) {
            const QByteArray a = askThenHalfClose(m_sim.port(), "AZ EL\n");
            answered += QRegularExpression("^AZ-?\\d+\\.\\d\\d EL-?\\d+\\.\\d\\d\n$").match(QString(a)).hasMatch();
        }
        QCOMPARE(answered, 20);
        // An unterminated last line is answered too.
        for (int i = 0; i < 20; ++i)
            QCOMPARE(askThenHalfClose(m_sim.port(), "GE\nVE"), QByteArray("GE1\nVESlewSim-1.0\n"));
        // On a slow line the held-back answer leaves at once rather than never.
        SlewSimProcess slow;
        QVERIFY2(slow.start({"--listen", "127.0.0.1:0", "--latency-ms", "300"}), qPrintable(slow.error()));
        for (int i = 0; i < 5; ++i)
            QCOMPARE(askThenHalfClose(slow.port(), "GE\n"), QByteArray("GE1\n"));
    }

    void clientsBeyondTheLimitAreRefused()
    {
        SlewSimProcess sim;
        QVERIFY2(sim.start({"--listen", "127.0.0.1:0", "--max-clients", "3"}), qPrintable(sim.error()));
        SimClient a, b, c;
        for (SimClient *client : {&a, &b, &c}) {
            QVERIFY(client->connectTo(sim.port()));
            QCOMPARE(client->ask("GE\n"), QByteArray("GE1\n"));
        }
        // The fourth reads why, and is closed.
        SimClient d;
        QSignalSpy refused(&d.socket(), &QTcpSocket::disconnected);
        QVERIFY(d.connectTo(sim.port()));
        QVERIFY(refused.wait(5000));
        QCOMPARE(d.socket().readAll(), QByteArray("ALbusy:max-clients=3\n"));
        // One leaves: the next is served.
        a.socket().disconnectFromHost();
        QVERIFY(QTest::qWaitFor(
            [&] {
                SimClient e;
                return e.connectTo(sim.port()) && e.ask("GE\n") == "GE1\n";
            },
            10000));
        QCOMPARE(b.ask("GE\n"), QByteArray("GE1\n"));
        // A nonsense limit is a clear error.
        SlewSimProcess bad;
        QVERIFY(!bad.start({"--listen", "127.0.0.1:0", "--max-clients", "0"}));
        QVERIFY2(bad.error().contains("--max-clients"), qPrintable(bad.error()));
    }

    void runningOutOfDescriptorsDoesNotSpin()
    {
        // 64 descriptors and 200 clients: slew-sim runs low long before the
        // client limit (raised here so that it does not step in first).
        SlewSimProcess sim;
        QVERIFY2(sim.start({"--listen", "127.0.0.1:0", "--max-clients", "500"},
                           [] {
                               const rlimit few{64, 64};
                               ::setrlimit(RLIMIT_NOFILE, &few);
                           }),
                 qPrintable(sim.error()));
        QProcess *process = sim.process();
        QByteArray notices;
        auto noticed = [&](const char *text) {
            notices += process->readAllStandardError();
            return notices.contains(text);
        };
        std::list<QTcpSocket> clients;
        for (int i = 0; i < 200; ++i) {
            clients.emplace_back();
            clients.back().connectToHost(QHostAddress::LocalHost, sim.port());
        }
        for (QTcpSocket &c : clients)
            c.write("GE\n");
        QVERIFY2(QTest::qWaitFor([&] { return noticed("new connections wait"); }, 10000), notices.constData());

        const double share = cpuShareOver(process->processId(), 2000);
        qInfo("slew-sim out of descriptors: %.1f %% of a core", 100 * share);
        QVERIFY2(share >= 0 && share < 0.2, qPrintable(QString::number(share)));

        // Every client is answered: those taken at once, and the waiting ones
        // as the first leave.
        int answered = 0;
        QByteArray wrong;
        QVERIFY(QTest::qWaitFor([&] { return takeOneAnswerEach(clients, "GE1\n", &answered, &wrong); }, 30000));
        QCOMPARE(answered, 200);
        QVERIFY2(wrong.isEmpty(), wrong.constData());
        QVERIFY2(noticed("accepting connections again"), notices.constData());
    }

    void cleanStopOnSigterm()
    {
        QCOMPARE(m_sim.stop(), 0);
        QVERIFY(m_sim.standardError().contains("rejected"));
    }

    void cleanStopOnSigint()
    {
        SlewSimProcess sim;
        QVERIFY2(sim.start({"--listen", "127.0.0.1:0"}), qPrintable(sim.error()));
        QSignalSpy finished(sim.process(), &QProcess::finished);
        ::kill(pid_t(sim.process()->processId()), SIGINT);
        QVERIFY(finished.wait(5000));
        QCOMPARE(sim.process()->exitStatus(), QProcess::NormalExit);
        QCOMPARE(sim.process()->exitCode(), 0);
    }

    void badFlagIsAClearError()
    {
        SlewSimProcess sim;
        QVERIFY(!sim.start({"--listen", "127.0.0.1:0", "--az-max", "500"}));
        QVERIFY2(sim.error().contains("az_max"), qPrintable(sim.error()));
    }

    void unsolicitedPushes()
    {
        SlewSimProcess sim;
        QVERIFY2(sim.start({"--listen", "127.0.0.1:0", "--unsolicited"}), qPrintable(sim.error()));
        SimClient c;
        QVERIFY(c.connectTo(sim.port()));
        const QByteArray first = c.readLines(3);
        QCOMPARE(first, QByteArray("AZ0.00\nEL0.00\nIP0,25.00\n"));
        c.socket().write("AZ5\n");
        QByteArray seen;
        while (!seen.contains("GS262\n")) {
            const QByteArray line = c.readLines(1);
            QVERIFY(!line.isEmpty());
            seen += line;
        }
        QVERIFY(seen.contains("CR10,5.00\n"));
        QVERIFY(seen.contains("VESlewSim-1.0\n"));
    }

    void faultsFromTheCommandLine_data()
    {
        QTest::addColumn<QStringList>("flags");
        QTest::addColumn<QByteArray>("command");
        QTest::addColumn<QByteArray>("error");
        QTest::addColumn<QByteArray>("status");
        QTest::newRow("jam") << QStringList{"--jam", "az", "--jam-after", "0.3"} << QByteArray("AZ40\n")
                             << QByteArray("GE8\n") << QByteArray("GS264\n");
        QTest::newRow("frozen encoder") << QStringList{"--freeze", "el"} << QByteArray("EL30\n") << QByteArray("GE2\n")
                                        << QByteArray("GS2049\n");
        QTest::newRow("noisy encoder") << QStringList{"--noise-az", "0.5"} << QByteArray("GS\n") << QByteArray("GE2\n")
                                       << QByteArray("GS264\n");
        QTest::newRow("missing end stop") << QStringList{"--no-endstop", "az", "--start-el", "2"}
                                          << QByteArray("RESET\n") << QByteArray("GE4\n") << QByteArray("GS1032\n");
    }
    void faultsFromTheCommandLine()
    {
        QFETCH(QStringList, flags);
        QFETCH(QByteArray, command);
        QFETCH(QByteArray, error);
        QFETCH(QByteArray, status);
        SlewSimProcess sim;
        QVERIFY2(sim.start(QStringList{"--listen", "127.0.0.1:0", "--time-scale", "4"} + flags), qPrintable(sim.error()));
        SimClient c;
        QVERIFY(c.connectTo(sim.port()));
        c.socket().write(command);
        QElapsedTimer timer;
        timer.start();
        QByteArray got;
        while (got != error && timer.elapsed() < 10000)
            got = c.ask("GE\n");
        QCOMPARE(got, error);
        QVERIFY(eventuallyOn(c, "GS\n", status));
    }

    void latencyAndDroppedConnectionFromTheCommandLine()
    {
        SlewSimProcess sim;
        QVERIFY2(sim.start({"--listen", "127.0.0.1:0", "--latency-ms", "200", "--drop-after", "1.5"}),
                 qPrintable(sim.error()));
        SimClient c;
        QVERIFY(c.connectTo(sim.port()));
        QElapsedTimer timer;
        timer.start();
        QCOMPARE(c.ask("GE\n"), QByteArray("GE1\n"));
        QVERIFY(timer.elapsed() >= 190);
        QSignalSpy gone(&c.socket(), &QTcpSocket::disconnected);
        QVERIFY(gone.wait(5000));
        QVERIFY(timer.elapsed() >= 1400);
    }

private:
    static bool eventuallyOn(SimClient &c, const QByteArray &query, const QByteArray &expected)
    {
        QElapsedTimer timer;
        timer.start();
        while (timer.elapsed() < 10000) {
            if (c.ask(query) == expected)
                return true;
        }
        return false;
    }
};

QTEST_GUILESS_MAIN(TestSlewSimTcp)
#include "tst_slewsimtcp.moc"
