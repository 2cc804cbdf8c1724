// SPDX-License-Identifier: GPL-3.0-or-later
// `slew --headless` as a station service, run as a real process: it serves
// rotctld for a tracker, steers slew-sim over TCP, reconnects after the
// rotator goes away, and stops the rotator when told to quit (SIGTERM): at
// rest near where it was, on a worm gear and on a free-running drive.

#include "../sim/slewsimprocess.h"
#include "../common/hamlibprocess.h"

#include <QElapsedTimer>
#include <QFile>
#include <QPointF>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>

class HeadlessTest : public QObject {
    Q_OBJECT
private slots:
    void servesTrackersAndStopsOnSigterm();
    void sigtermLeavesTheAntennaAtRest_data();
    void sigtermLeavesTheAntennaAtRest();
    void reconnectsAfterTheRotatorReturns();
    void refusesABadListenAddress();

private:
    bool startSlew(QProcess &slew, const QStringList &args, quint16 *rotctldPort);
    static QByteArray ask(QTcpSocket &s, const QByteArray &line);
    static QPointF positionOf(const QByteArray &reply); // "AZ12.00 EL3.00"
};

QPointF HeadlessTest::positionOf(const QByteArray &reply)
{
    const QList<QByteArray> words = reply.trimmed().split(' ');
    if (words.size() != 2)
        return QPointF(qQNaN(), qQNaN());
    return QPointF(words[0].mid(2).toDouble(), words[1].mid(2).toDouble());
}

bool HeadlessTest::startSlew(QProcess &slew, const QStringList &args, quint16 *rotctldPort)
{
    slew.setProgram(qEnvironmentVariable("SLEW_BIN"));
    slew.setArguments(QStringList{"--headless"} + args);
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove("QT_QPA_PLATFORM");
    env.remove("DISPLAY");
    env.remove("WAYLAND_DISPLAY"); // a service has no display
    slew.setProcessEnvironment(env);
    slew.start();
    QByteArray out;
    const bool ready = QTest::qWaitFor(
        [&] {
            out += slew.readAllStandardOutput();
            return out.contains("rotctld listening on") || slew.state() == QProcess::NotRunning;
        },
        10000);
    if (!ready || slew.state() == QProcess::NotRunning)
        return false;
    const qsizetype at = out.indexOf("rotctld listening on");
    const QByteArray line = out.mid(at, out.indexOf('\n', at) - at);
    *rotctldPort = quint16(line.mid(line.lastIndexOf(':') + 1).toUInt());
    return *rotctldPort != 0;
}

QByteArray HeadlessTest::ask(QTcpSocket &s, const QByteArray &line)
{
    QSignalSpy ready(&s, &QTcpSocket::readyRead);
    s.write(line + '\n');
    if (!ready.wait(5000))
        return {};
    return s.readAll();
}

void HeadlessTest::servesTrackersAndStopsOnSigterm()
{
    QTemporaryDir dir;
    const QString received = dir.filePath("received.log");
    SlewSimProcess sim;
    QVERIFY2(sim.start({"--listen", "127.0.0.1:0", "--log-received", received}), qPrintable(sim.error()));
    QProcess slew;
    quint16 port = 0;
    QVERIFY2(startSlew(slew, {"--connect", QStringLiteral("tcp://127.0.0.1:%1").arg(sim.port()), "--rotctld-listen",
                               "127.0.0.1:0"},
                       &port),
             slew.readAllStandardError().constData());

    QTcpSocket tracker;
    tracker.connectToHost(QHostAddress::LocalHost, port);
    QTRY_COMPARE(tracker.state(), QAbstractSocket::ConnectedState);
    // Once the rotator is reached, positions flow.
    QVERIFY(QTest::qWaitFor([&] { return ask(tracker, "p").count('\n') == 2; }, 10000));
    QCOMPARE(ask(tracker, "P 120 30"), QByteArray("RPRT 0\n"));
    tracker.disconnectFromHost();

    auto log = [&] {
        QFile f(received);
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    };
    QTRY_VERIFY(log().contains("AZ120.00 EL30.00"));
    const qsizetype before = log().count("SA SE");

    // SIGTERM: the rotator is stopped before Slew exits.
    QSignalSpy finished(&slew, &QProcess::finished);
    ::kill(pid_t(slew.processId()), SIGTERM);
    QVERIFY(finished.wait(10000));
    QCOMPARE(slew.exitStatus(), QProcess::NormalExit);
    QCOMPARE(slew.exitCode(), 0);
    QTRY_VERIFY(log().count("SA SE") > before);
    const QByteArray out = slew.readAllStandardOutput();
    QVERIFY2(out.contains("rotator stopped"), out.constData());
}

void HeadlessTest::sigtermLeavesTheAntennaAtRest_data()
{
    QTest::addColumn<QString>("drive");
    QTest::addColumn<int>("restWithinMs");
    QTest::addColumn<double>("maxTravel");
    QTest::newRow("worm gear") << QStringLiteral("worm") << 1000 << 2.0;
    // A free drive coasts on SA SE; the zero speed that follows brakes it,
    // and Slew waits for that to leave before it exits.
    QTest::newRow("free drive") << QStringLiteral("free") << 2000 << 360.0;
}

void HeadlessTest::sigtermLeavesTheAntennaAtRest()
{
    QFETCH(QString, drive);
    QFETCH(int, restWithinMs);
    QFETCH(double, maxTravel);
    QTemporaryDir dir;
    const QString received = dir.filePath("received.log");
    SlewSimProcess sim;
    QVERIFY2(sim.start({"--listen", "127.0.0.1:0", "--drive", drive, "--log-received", received}),
             qPrintable(sim.error()));
    QProcess slew;
    quint16 port = 0;
    QVERIFY2(startSlew(slew, {"--connect", QStringLiteral("tcp://127.0.0.1:%1").arg(sim.port()), "--rotctld-listen",
                               "127.0.0.1:0"},
                       &port),
             slew.readAllStandardError().constData());
    QTcpSocket tracker;
    tracker.connectToHost(QHostAddress::LocalHost, port);
    QTRY_COMPARE(tracker.state(), QAbstractSocket::ConnectedState);
    QVERIFY(QTest::qWaitFor([&] { return ask(tracker, "p").count('\n') == 2; }, 10000));
    QCOMPARE(ask(tracker, "P 300 80"), QByteArray("RPRT 0\n"));

    // A second client of the simulator watches the antenna itself.
    SimClient monitor;
    QVERIFY(monitor.connectTo(sim.port()));
    QPointF pressed;
    QVERIFY(QTest::qWaitFor(
        [&] {
            pressed = positionOf(monitor.ask("AZ EL\n"));
            return pressed.x() > 10.0;
        },
        15000));
    QSignalSpy finished(&slew, &QProcess::finished);
    ::kill(pid_t(slew.processId()), SIGTERM);
    QElapsedTimer sinceStop;
    sinceStop.start();
    QVERIFY(finished.wait(10000));
    QCOMPARE(slew.exitCode(), 0);

    QPointF first, second;
    QVERIFY(QTest::qWaitFor([&] { return sinceStop.elapsed() >= restWithinMs; }, restWithinMs + 5000));
    first = positionOf(monitor.ask("AZ EL\n"));
    const qint64 firstAt = sinceStop.elapsed();
    QVERIFY(QTest::qWaitFor([&] { return sinceStop.elapsed() >= firstAt + 1000; }, 6000));
    second = positionOf(monitor.ask("AZ EL\n"));
    const QString trace = QStringLiteral("SIGTERM at %1/%2, then %3/%4, a second later %5/%6")
                              .arg(pressed.x())
                              .arg(pressed.y())
                              .arg(first.x())
                              .arg(first.y())
                              .arg(second.x())
                              .arg(second.y());
    qInfo("%s: %s", QTest::currentDataTag(), qPrintable(trace));
    QVERIFY2(std::abs(second.x() - first.x()) < 0.05 && std::abs(second.y() - first.y()) < 0.05, qPrintable(trace));
    QVERIFY2(std::abs(first.x() - pressed.x()) < maxTravel && std::abs(first.y() - pressed.y()) < maxTravel,
             qPrintable(trace));
    QFile log(received);
    QVERIFY(log.open(QIODevice::ReadOnly));
    const QByteArray lines = log.readAll();
    QVERIFY(lines.contains("SA SE"));
    QVERIFY2(lines.contains("VL000 VU000"), lines.right(300).constData()); // the hold went out before the exit
}

void HeadlessTest::reconnectsAfterTheRotatorReturns()
{
    SlewSimProcess sim;
    QVERIFY2(sim.start({"--listen", "127.0.0.1:0"}), qPrintable(sim.error()));
    const quint16 simPort = sim.port();
    QProcess slew;
    quint16 port = 0;
    QVERIFY(startSlew(slew, {"--connect", QStringLiteral("tcp://127.0.0.1:%1").arg(simPort), "--rotctld-listen",
                             "127.0.0.1:0"},
                      &port));
    QTcpSocket tracker;
    tracker.connectToHost(QHostAddress::LocalHost, port);
    QTRY_COMPARE(tracker.state(), QAbstractSocket::ConnectedState);
    QVERIFY(QTest::qWaitFor([&] { return ask(tracker, "p").count('\n') == 2; }, 10000));

    // The rotator goes away: trackers get an error code, not a stale lie forever.
    sim.stop();
    QVERIFY(QTest::qWaitFor([&] { return ask(tracker, "p") == "RPRT -6\n"; }, 10000));
    // It comes back on the same port: Slew finds it again by itself.
    SlewSimProcess again;
    QVERIFY2(again.start({"--listen", QStringLiteral("127.0.0.1:%1").arg(simPort)}), qPrintable(again.error()));
    QVERIFY(QTest::qWaitFor([&] { return ask(tracker, "p").count('\n') == 2; }, 30000));
    slew.terminate();
    QTRY_COMPARE(slew.state(), QProcess::NotRunning);
    QVERIFY(slew.readAllStandardOutput().contains("retrying"));
}

void HeadlessTest::refusesABadListenAddress()
{
    QProcess slew;
    slew.setProgram(qEnvironmentVariable("SLEW_BIN"));
    slew.setArguments({"--headless", "--connect", "sim:", "--rotctld-listen", "nonsense"});
    QSignalSpy finished(&slew, &QProcess::finished);
    slew.start();
    QVERIFY(finished.wait(10000));
    QCOMPARE(slew.exitCode(), 2);
    QVERIFY(slew.readAllStandardError().contains("expected ADDRESS:PORT"));
}

QTEST_GUILESS_MAIN(HeadlessTest)
#include "tst_headless.moc"
