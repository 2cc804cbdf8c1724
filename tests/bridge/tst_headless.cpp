// SPDX-License-Identifier: GPL-3.0-or-later
// `slew --headless` as a station service, run as a real process: it serves
// rotctld for a tracker, steers slew-sim over TCP, reconnects after the
// rotator goes away, and stops the rotator when told to quit (SIGTERM): at
// rest near where it was, on a worm gear and on a free-running drive.

#include "../sim/slewsimprocess.h"
#include "../common/halfclose.h"
#include "../common/hamlibprocess.h"

#include <QElapsedTimer>
#include <QFile>
#include <QPointF>
#include <QSet>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>

#include <QRandomGenerator>
#include <QRegularExpression>
#include <QTimer>

#include <csignal>
#include <array>
#include <functional>
#include <list>
#include <sys/resource.h>

class HeadlessTest : public QObject {
    Q_OBJECT
private slots:
    void servesTrackersAndStopsOnSigterm();
    void sigtermLeavesTheAntennaAtRest_data();
    void sigtermLeavesTheAntennaAtRest();
    void reconnectsAfterTheRotatorReturns();
    void repeatedTargetReachesTheRotatorAfterStopAndReconnect();
    void refusesABadListenAddress();
    void servesOneRotctldPortPerRotor();
    void refusesABadRotorList();
    void tracksAPassAndHoldsOffRemoteTrackers();
    void holdsAFixedDirection();
    void logsAlarmsInTheBannersWords();
    void refusesABadTrack();
    void runningOutOfDescriptorsDoesNotSpin();
    void hostileClientCannotFloodTheLog();
    void servesASpidRotatorOnASerialLine();
    void servesTheFirmwareInTheField_data();
    void servesTheFirmwareInTheField();
    void movesNothingItCannotRead();

private:
    // Starts `slew --headless ARGS` and reads its log up to the rotctld
    // server's ready line (kept in m_startupLog) for the port.
    bool startSlew(QProcess &slew, const QStringList &args, quint16 *rotctldPort,
                   const std::function<void()> &childSetup = {});
    QByteArray m_startupLog;
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

bool HeadlessTest::startSlew(QProcess &slew, const QStringList &args, quint16 *rotctldPort,
                             const std::function<void()> &childSetup)
{
    if (childSetup)
        slew.setChildProcessModifier(childSetup);
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
            // The whole line: the port at its end may come in a later read.
            const qsizetype at = out.indexOf("rotctld listening on");
            return (at >= 0 && out.indexOf('\n', at) > at) || slew.state() == QProcess::NotRunning;
        },
        10000);
    if (!ready || slew.state() == QProcess::NotRunning)
        return false;
    m_startupLog = out;
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
                               "127.0.0.1:0", "--qth", "JO65hq"},
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
    QVERIFY2(out.contains("stop sent (Slew is ending: signal 15)"), out.constData());
    // The station it was given, checked and logged.
    QVERIFY2(m_startupLog.contains("station: 55.6875° N, 12.6250° E, 0 m above the ellipsoid — locator JO65hq"),
             m_startupLog.constData());
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

void HeadlessTest::repeatedTargetReachesTheRotatorAfterStopAndReconnect()
{
    QTemporaryDir dir;
    auto received = [&](const QString &name) {
        QFile f(dir.filePath(name));
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    };
    SlewSimProcess sim;
    QVERIFY2(sim.start({"--listen", "127.0.0.1:0", "--log-received", dir.filePath("first.log")}), qPrintable(sim.error()));
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

    // P, S, the same P: both reach the rotator.
    QCOMPARE(ask(tracker, "P 100 40"), QByteArray("RPRT 0\n"));
    QTRY_COMPARE(received("first.log").count("AZ100.00 EL40.00"), 1);
    QCOMPARE(ask(tracker, "S"), QByteArray("RPRT 0\n"));
    QTRY_VERIFY(received("first.log").contains("SA SE"));
    QCOMPARE(ask(tracker, "P 100 40"), QByteArray("RPRT 0\n"));
    QTRY_COMPARE(received("first.log").count("AZ100.00 EL40.00"), 2);

    // The rotator goes away and comes back on the same port.
    sim.stop();
    QVERIFY(QTest::qWaitFor([&] { return ask(tracker, "p") == "RPRT -6\n"; }, 10000));
    SlewSimProcess again;
    QVERIFY2(again.start({"--listen", QStringLiteral("127.0.0.1:%1").arg(simPort), "--log-received",
                          dir.filePath("second.log")}),
             qPrintable(again.error()));
    QVERIFY(QTest::qWaitFor([&] { return ask(tracker, "p").count('\n') == 2; }, 30000));
    // Slew does not move the antenna by itself after the blip...
    QVERIFY(!received("second.log").contains("AZ100.00 EL40.00"));
    // ...but the tracker's next P, identical, goes out, and one inside the
    // deadband of the old target too.
    QCOMPARE(ask(tracker, "P 100 40"), QByteArray("RPRT 0\n"));
    QTRY_COMPARE(received("second.log").count("AZ100.00 EL40.00"), 1);
    QCOMPARE(ask(tracker, "S"), QByteArray("RPRT 0\n"));
    QCOMPARE(ask(tracker, "P 100.3 40.2"), QByteArray("RPRT 0\n"));
    QTRY_COMPARE(received("second.log").count("AZ100.30 EL40.20"), 1);
    slew.terminate();
    QTRY_COMPARE(slew.state(), QProcess::NotRunning);
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

void HeadlessTest::servesOneRotctldPortPerRotor()
{
    // A Micro-2g with four rotors on one line, and a tracker per rotor.
    QTemporaryDir dir;
    const QString received = dir.filePath("received.log");
    SlewSimProcess sim;
    QVERIFY2(sim.start({"--listen", "127.0.0.1:0", "--dialect", "micro2g", "--time-scale", "4", "--log-received", received}),
             qPrintable(sim.error()));
    QProcess slew;
    quint16 first = 0;
    QVERIFY2(startSlew(slew, {"--connect", QStringLiteral("tcp://127.0.0.1:%1").arg(sim.port()), "--dialect", "micro2g",
                               "--rotctld-listen", "127.0.0.1:0", "--rotors", "1-4"},
                       &first),
             slew.readAllStandardError().constData());
    // Every rotor says which port is its own.
    QByteArray out = m_startupLog;
    QVERIFY(QTest::qWaitFor([&] {
        out += slew.readAllStandardOutput();
        return out.count("rotctld listening on") == 4 && out.endsWith('\n'); // the fourth line whole
    }, 10000));
    QMap<int, quint16> ports;
    const QRegularExpression ready(QStringLiteral("rotor (\\d): rotctld listening on 127.0.0.1:(\\d+)"));
    for (auto m = ready.globalMatch(QString::fromUtf8(out)); m.hasNext();) {
        const auto match = m.next();
        ports[match.captured(1).toInt()] = quint16(match.captured(2).toUInt());
    }
    QCOMPARE(ports.keys(), (QList<int>{1, 2, 3, 4}));
    QCOMPARE(ports[1], first);
    QCOMPARE(QSet<quint16>(ports.begin(), ports.end()).size(), 4);

    std::array<QTcpSocket, 4> trackers;
    for (int n = 1; n <= 4; ++n) {
        trackers[size_t(n - 1)].connectToHost(QHostAddress::LocalHost, ports[n]);
        QTRY_COMPARE(trackers[size_t(n - 1)].state(), QAbstractSocket::ConnectedState);
        QVERIFY(QTest::qWaitFor([&] { return ask(trackers[size_t(n - 1)], "p").count('\n') == 2; }, 10000));
    }
    QCOMPARE(ask(trackers[1], "P 30 0"), QByteArray("RPRT 0\n"));
    QCOMPARE(ask(trackers[3], "P 60 0"), QByteArray("RPRT 0\n"));
    // Azimuth only: an elevation is refused, with Hamlib's "not available".
    QCOMPARE(ask(trackers[2], "P 10 20"), QByteArray("RPRT -11\n"));

    // Each port turns its own rotor: 2 and 4 move, 1 and 3 stay at the north stop.
    auto azimuthOf = [&](int n) { return ask(trackers[size_t(n - 1)], "p").split('\n').front().toDouble(); };
    QVERIFY(QTest::qWaitFor([&] { return azimuthOf(2) > 15 && azimuthOf(4) > 30; }, 15000));
    QCOMPARE(azimuthOf(1), 0.0);
    QCOMPARE(azimuthOf(3), 0.0);

    // SIGTERM stops every rotor before Slew exits.
    for (QTcpSocket &t : trackers)
        t.disconnectFromHost();
    QSignalSpy finished(&slew, &QProcess::finished);
    ::kill(pid_t(slew.processId()), SIGTERM);
    QVERIFY(finished.wait(10000));
    QCOMPARE(slew.exitCode(), 0);
    out += slew.readAllStandardOutput();
    for (int n = 1; n <= 4; ++n)
        QVERIFY2(out.contains(QStringLiteral("rotor %1: stop sent (Slew is ending: signal 15)").arg(n).toUtf8()), out.constData());
    // The stops left Slew before it exited; the simulator, another process,
    // reads and records them in its own time, which under load can be after
    // Slew is gone. So its record is awaited, not read once.
    QByteArray wire;
    const bool allStopsRecorded = QTest::qWaitFor(
        [&] {
            QFile log(received);
            wire = log.open(QIODevice::ReadOnly) ? log.readAll() : QByteArray();
            for (int n = 1; n <= 4; ++n)
                if (!wire.contains(QStringLiteral("S%1").arg(n).toUtf8()))
                    return false;
            return true;
        },
        10000);
    QVERIFY2(allStopsRecorded, wire.constData());
}

void HeadlessTest::refusesABadRotorList()
{
    for (const char *list : {"5", "1,1", "2-1", "one"}) {
        QProcess slew;
        QSignalSpy finished(&slew, &QProcess::finished);
        slew.start(qEnvironmentVariable("SLEW_BIN"), {"--headless", "--connect", "sim:?dialect=micro2g", "--rotors", list});
        QVERIFY(finished.wait(10000));
        QCOMPARE(slew.exitCode(), 2);
        const QByteArray err = slew.readAllStandardError();
        QVERIFY2(err.contains("--rotors"), err.constData());
    }
}

void HeadlessTest::tracksAPassAndHoldsOffRemoteTrackers()
{
    // A rehearsal: FLOCK 2P-1's pass over JO65hq on 2018-01-22 (LOS 07:51:03
    // UTC) joined a minute before LOS, station clock and slew-sim both 20x,
    // slew-sim as a real process on its pseudo-terminal, opened as a serial port.
    QTemporaryDir dir;
    const QString pty = dir.filePath("rotator");
    SlewSimProcess sim;
    QVERIFY2(sim.start({"--pty", pty, "--time-scale", "20", "--az-max", "450", "--el-max", "180"}), qPrintable(sim.error()));
    QProcess slew;
    quint16 port = 0;
    QVERIFY2(startSlew(slew, {"--connect", "serial:" + pty + "?baud=9600", "--limits", "0:450,0:180", "--qth",
                               "JO65hq", "--tle", SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle", "--track",
                               "FLOCK 2P-1", "--clock-start", "2018-01-22T07:50:00Z", "--clock-rate", "20",
                               "--rotctld-listen", "127.0.0.1:0"},
                       &port),
             slew.readAllStandardError().constData());
    QByteArray out = m_startupLog;
    auto logged = [&](const char *text) {
        return QTest::qWaitFor([&] {
            out += slew.readAllStandardOutput();
            return out.contains(text);
        }, 20000);
    };
    QVERIFY2(logged("track: plan: "), out.constData());
    QVERIFY(out.contains("track: next pass: FLOCK 2P-1, AOS 2018-01-22T"));
    QVERIFY2(logged("remote control held by Slew's own tracking"), out.constData());
    // While Slew tracks, a remote tracker's move is refused (Hamlib's -9, rejected).
    QTcpSocket tracker;
    tracker.connectToHost(QHostAddress::LocalHost, port);
    QTRY_COMPARE(tracker.state(), QAbstractSocket::ConnectedState);
    QCOMPARE(ask(tracker, "P 10 10"), QByteArray("RPRT -9\n"));
    // At LOS: the figures, then control handed back.
    QVERIFY2(logged("track: LOS: pointing error RMS "), out.constData());
    QVERIFY2(logged("remote control handed back"), out.constData());
    const QByteArray after = ask(tracker, "P 10 10");
    QVERIFY2(after == "RPRT 0\n", (after + out).constData());
    // And the next pass is planned.
    QVERIFY2(logged("track: next pass: FLOCK 2P-1, AOS 2018-01-22T09:15:45Z"), out.constData());
    QSignalSpy finished(&slew, &QProcess::finished);
    ::kill(pid_t(slew.processId()), SIGTERM);
    QVERIFY(finished.wait(10000));
    QCOMPARE(slew.exitCode(), 0);
}

void HeadlessTest::servesASpidRotatorOnASerialLine()
{
    // The station service on a Rot2Prog: slew-sim on a pty at 600 baud,
    // opened as a serial port. A tracker sets and reads through rotctld;
    // SIGTERM stops the rotator with SPID's stop frame before Slew exits.
    QTemporaryDir dir;
    const QString pty = dir.filePath("rot2prog"), received = dir.filePath("received.log");
    SlewSimProcess sim;
    QVERIFY2(sim.start({"--pty", pty, "--dialect", "rot2prog", "--baud", "600", "--time-scale", "4", "--model", "satnogs",
                        "--log-received", received}),
             qPrintable(sim.error()));
    QProcess slew;
    quint16 port = 0;
    QVERIFY2(startSlew(slew, {"--connect", QStringLiteral("serial:%1?baud=600").arg(pty), "--dialect", "rot2prog",
                               "--rotctld-listen", "127.0.0.1:0"},
                       &port),
             slew.readAllStandardError().constData());
    QTcpSocket tracker;
    tracker.connectToHost(QHostAddress::LocalHost, port);
    QTRY_COMPARE(tracker.state(), QAbstractSocket::ConnectedState);
    QVERIFY(QTest::qWaitFor([&] { return ask(tracker, "p").count('\n') == 2; }, 15000));
    QCOMPARE(ask(tracker, "P 40 20"), QByteArray("RPRT 0\n"));
    QPointF at;
    QVERIFY2(QTest::qWaitFor([&] {
        const QList<QByteArray> lines = ask(tracker, "p").trimmed().split('\n');
        at = lines.size() == 2 ? QPointF(lines[0].toDouble(), lines[1].toDouble()) : QPointF();
        return std::abs(at.x() - 40) < 0.3 && std::abs(at.y() - 20) < 0.3;
    }, 30000), qPrintable(QStringLiteral("at %1, %2").arg(at.x()).arg(at.y())));
    QCOMPARE(ask(tracker, "R 1"), QByteArray("RPRT -11\n")); // no homing on a Rot2Prog
    auto log = [&] {
        QFile f(received);
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    };
    const QByteArray stopFrame = "W" + QByteArray("\\x00").repeated(10) + "\\x0f \n";
    const qsizetype before = log().count(stopFrame);
    QSignalSpy finished(&slew, &QProcess::finished);
    ::kill(pid_t(slew.processId()), SIGTERM);
    QVERIFY(finished.wait(10000));
    QCOMPARE(slew.exitCode(), 0);
    QTRY_VERIFY_WITH_TIMEOUT(log().count(stopFrame) > before, 5000);

    // A simulator's URI names its dialect: without --dialect, Slew takes it.
    QProcess hinted;
    QVERIFY2(startSlew(hinted, {"--connect", "sim:?dialect=rot2prog", "--rotctld-listen", "127.0.0.1:0"}, &port),
             hinted.readAllStandardError().constData());
    QTcpSocket second;
    second.connectToHost(QHostAddress::LocalHost, port);
    QTRY_COMPARE(second.state(), QAbstractSocket::ConnectedState);
    QVERIFY(QTest::qWaitFor([&] { return ask(second, "p").count('\n') == 2; }, 15000));
    QSignalSpy hintedFinished(&hinted, &QProcess::finished);
    ::kill(pid_t(hinted.processId()), SIGTERM);
    QVERIFY(hintedFinished.wait(10000));
}

void HeadlessTest::holdsAFixedDirection()
{
    // A fixed azimuth and elevation (a drift scan, a beacon) through
    // slew-sim over TCP, 20x: held until SIGTERM, remote trackers held off.
    SlewSimProcess sim;
    QVERIFY2(sim.start({"--listen", "127.0.0.1:0", "--time-scale", "20"}), qPrintable(sim.error()));
    QProcess slew;
    quint16 port = 0;
    QVERIFY2(startSlew(slew, {"--connect", QStringLiteral("tcp://127.0.0.1:%1").arg(sim.port()), "--qth", "JO65hq",
                               "--track", "azel:123.5,41", "--rotctld-listen", "127.0.0.1:0"},
                       &port),
             slew.readAllStandardError().constData());
    QByteArray out = m_startupLog;
    QVERIFY2(QTest::qWaitFor([&] {
        out += slew.readAllStandardOutput();
        return out.contains("track: holding azimuth 123.50°, elevation 41.00° until ");
    }, 10000), out.constData());
    QTcpSocket client;
    client.connectToHost(QHostAddress::LocalHost, port);
    QTRY_COMPARE(client.state(), QAbstractSocket::ConnectedState);
    QPointF at;
    QVERIFY2(QTest::qWaitFor([&] {
        const QList<QByteArray> lines = ask(client, "p").trimmed().split('\n');
        at = lines.size() == 2 ? QPointF(lines[0].toDouble(), lines[1].toDouble()) : QPointF();
        return std::abs(at.x() - 123.5) < 0.3 && std::abs(at.y() - 41) < 0.3;
    }, 20000), qPrintable(QStringLiteral("at %1, %2").arg(at.x()).arg(at.y())));
    QCOMPARE(ask(client, "P 10 10"), QByteArray("RPRT -9\n"));
    QSignalSpy finished(&slew, &QProcess::finished);
    ::kill(pid_t(slew.processId()), SIGTERM);
    QVERIFY(finished.wait(10000));
    QCOMPARE(slew.exitCode(), 0);
}

void HeadlessTest::logsAlarmsInTheBannersWords()
{
    // A jammed azimuth on the built-in simulator: the motor error the
    // window's banner shows ("Controller error: ...", "Axis error (GS): ...",
    // from the one alarm monitor) is in the service's log, in those words.
    QProcess slew;
    quint16 port = 0;
    QVERIFY2(startSlew(slew, {"--connect", "sim:?jam=az&jam_after=0.3", "--rotctld-listen", "127.0.0.1:0"}, &port),
             slew.readAllStandardError().constData());
    QByteArray out = m_startupLog;
    QTcpSocket client;
    client.connectToHost(QHostAddress::LocalHost, port);
    QTRY_COMPARE(client.state(), QAbstractSocket::ConnectedState);
    QVERIFY(QTest::qWaitFor([&] { return ask(client, "p").count('\n') == 2; }, 10000));
    QCOMPARE(ask(client, "P 90 0"), QByteArray("RPRT 0\n"));
    const QRegularExpression alarm(QStringLiteral("Z alarm: (Controller error|Axis error \\(GS\\)): [^\n]*motor"),
                                   QRegularExpression::CaseInsensitiveOption);
    QVERIFY2(QTest::qWaitFor([&] {
        out += slew.readAllStandardOutput();
        return alarm.match(QString::fromUtf8(out)).hasMatch();
    }, 15000), out.constData());
    QSignalSpy finished(&slew, &QProcess::finished);
    ::kill(pid_t(slew.processId()), SIGTERM);
    QVERIFY(finished.wait(10000));
    QCOMPARE(slew.exitCode(), 0);
}

void HeadlessTest::refusesABadTrack()
{
    const QString tle = QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle");
    const QList<QPair<QStringList, QByteArray>> cases{
        {{"--track", "FLOCK 2P-1", "--tle", tle}, "--track needs --qth"},
        {{"--track", "FLOCK 2P-1", "--qth", "JO65hq"}, "no element sets: give --tle FILE"},
        {{"--track", "NO SUCH BIRD", "--qth", "JO65hq", "--tle", tle}, "no satellite 'NO SUCH BIRD' in"},
        // Elements from 2018 on today's clock: past the limit, as in the window.
        {{"--track", "FLOCK 2P-1", "--qth", "JO65hq", "--tle", tle},
         "FLOCK 2P-1 is not tracked: its elements are"},
        {{"--track", "FLOCK 2P-1", "--qth", "JO65hq", "--tle", tle, "--max-element-age", "0"},
         "--max-element-age: "},
        {{"--max-element-age", "3"}, "--max-element-age goes with --track"},
        {{"--track", "sun", "--qth", "JO65hq", "--clock-rate", "5"}, "--clock-rate"},
        {{"--track", "sun", "--qth", "JO65hq", "--clock-start", "yesterday"}, "--clock-start"},
        {{"--track", "moon", "--qth", "JO65hq", "--min-el", "95"}, "--min-el"},
        {{"--limits", "0:500,0:90"}, "--limits"},
        {{"--limits", "0-450"}, "AZMIN:AZMAX,ELMIN:ELMAX"},
        {{"--tle", tle}, "goes with --track"},
        {{"--track", "azel:400,10", "--qth", "JO65hq"}, "azimuth 0..360"},
        {{"--track", "radec:25,10", "--qth", "JO65hq"}, "right ascension is in hours"},
        {{"--track", "radec:12:30:00", "--qth", "JO65hq"}, "radec:RA,DEC"},
    };
    for (const auto &[args, message] : cases) {
        QProcess slew;
        QSignalSpy finished(&slew, &QProcess::finished);
        slew.start(qEnvironmentVariable("SLEW_BIN"), QStringList{"--headless", "--connect", "sim:"} + args);
        QVERIFY(finished.wait(10000));
        QCOMPARE(slew.exitCode(), 2);
        const QByteArray err = slew.readAllStandardError();
        QVERIFY2(err.contains(message), (args.join(' ') + ": " + err).toUtf8().constData());
    }
}

void HeadlessTest::runningOutOfDescriptorsDoesNotSpin()
{
    // 64 descriptors and 200 trackers: the rotctld server runs low long
    // before its client limit (raised here so that it does not step in first).
    QProcess slew;
    quint16 port = 0;
    QVERIFY(startSlew(slew, {"--connect", "sim:", "--rotctld-listen", "127.0.0.1:0", "--rotctld-max-clients", "500"},
                      &port, [] {
                          const rlimit few{64, 64};
                          ::setrlimit(RLIMIT_NOFILE, &few);
                      }));
    QByteArray log;
    auto logged = [&](const char *text) {
        log += slew.readAllStandardOutput();
        return log.contains(text);
    };
    std::list<QTcpSocket> clients;
    for (int i = 0; i < 200; ++i) {
        clients.emplace_back();
        clients.back().connectToHost(QHostAddress::LocalHost, port);
    }
    for (QTcpSocket &c : clients)
        c.write("S\n");
    QVERIFY2(QTest::qWaitFor([&] { return logged("new connections wait"); }, 10000), log.right(2000).constData());

    const double share = cpuShareOver(slew.processId(), 2000);
    qInfo("slew --headless out of descriptors: %.1f %% of a core", 100 * share);
    QVERIFY2(share >= 0 && share < 0.2, qPrintable(QString::number(share)));

    // Every client is answered: those taken at once, and the waiting ones
    // as the first leave.
    int answered = 0;
    QByteArray wrong;
    QVERIFY(QTest::qWaitFor([&] { return takeOneAnswerEach(clients, "RPRT 0\n", &answered, &wrong); }, 30000));
    QCOMPARE(answered, 200);
    QVERIFY2(wrong.isEmpty(), wrong.constData());
    QVERIFY(logged("accepting connections again"));
    slew.terminate();
    QTRY_COMPARE(slew.state(), QProcess::NotRunning);
}

void HeadlessTest::hostileClientCannotFloodTheLog()
{
    QProcess slew;
    quint16 port = 0;
    QVERIFY(startSlew(slew, {"--connect", "sim:", "--rotctld-listen", "127.0.0.1:0"}, &port));
    QByteArray out;
    auto logged = [&](const QByteArray &text) {
        out += slew.readAllStandardOutput();
        return out.contains(text);
    };
    logged("");
    const qsizetype before = out.size();

    // 512 KiB of random bytes, laced with terminal escape sequences and
    // lines long and short, from one client, which then leaves.
    QRandomGenerator rng(11);
    QByteArray junk;
    const QByteArray escapes[] = {"\x1b[2J", "\x1b]0;owned\x07", "\x9b" "31m", "\x1b[31m", "\r", "\x08\x08\x08"};
    while (junk.size() < 512 * 1024) {
        if (rng.bounded(4) == 0)
            junk += escapes[rng.bounded(int(std::size(escapes)))];
        else if (rng.bounded(8) == 0)
            junk += '\n';
        else
            junk += char(rng.bounded(256));
    }
    QTcpSocket hostile;
    hostile.connectToHost(QHostAddress::LocalHost, port);
    QTRY_COMPARE(hostile.state(), QAbstractSocket::ConnectedState);
    const QByteArray peer = "127.0.0.1:" + QByteArray::number(hostile.localPort());
    hostile.write(junk);
    QVERIFY(QTest::qWaitFor([&] { return hostile.bytesToWrite() == 0; }, 20000));
    // An unknown line is logged once, as its refusal.
    QTcpSocket good;
    good.connectToHost(QHostAddress::LocalHost, port);
    QTRY_COMPARE(good.state(), QAbstractSocket::ConnectedState);
    QCOMPARE(ask(good, "Zebra"), QByteArray("RPRT -1\n"));
    QVERIFY(QTest::qWaitFor([&] { return logged("unknown command 'Z'"); }, 10000));
    hostile.disconnectFromHost();
    QVERIFY(QTest::qWaitFor([&] { return logged("rotctld client " + peer + " left"); }, 20000));

    const QByteArray flood = out.mid(before);
    qInfo("512 KiB of hostile input: %lld bytes of log in %lld lines", qint64(flood.size()), qint64(flood.count('\n')));
    QVERIFY2(flood.contains("more lines from " + peer + " suppressed"), flood.right(2000).constData());
    // Bounded: a burst of lines, each at most 200 characters after its time stamp.
    QVERIFY2(flood.size() < 12 * 1024, qPrintable(QString::number(flood.size())));
    for (const QByteArray &line : flood.split('\n')) {
        QVERIFY2(QString::fromUtf8(line).size() <= 25 + 200 + 30, line.constData());
        for (const char ch : line) {
            const auto u = static_cast<unsigned char>(ch);
            QVERIFY2(u >= 0x20 && u != 0x7f, line.toPercentEncoding().constData());
        }
        // No C1 controls either (U+0080..U+009F in UTF-8: C2 80..C2 9F).
        QVERIFY2(!QString::fromUtf8(line).contains(QRegularExpression("[\\x{80}-\\x{9f}]")), line.constData());
    }
    QCOMPARE(flood.count("Zebra"), 0); // the refusal names the command letter only, once
    QCOMPARE(flood.count("unknown command 'Z'"), 1);
    slew.terminate();
    QTRY_COMPARE(slew.state(), QProcess::NotRunning);
}

QTEST_GUILESS_MAIN(HeadlessTest)
#include "tst_headless.moc"

void HeadlessTest::servesTheFirmwareInTheField_data()
{
    // slew-sim's K3NG and SatNOGS personalities on a pty, the station
    // service on it as a serial port named by its URI, and Hamlib's own
    // `rotctl -m 2` as the tracker. `arrivesAt`: the azimuth after P 40 25
    // from 100 (K3NG lets go inside its 3° tolerance, 2.3° short; its
    // GS-232B reports whole degrees). `parks`: where park ends (K3NG's
    // Easycom has no PARK, and is parked with a go-to to 0/90 short of 0).
    QTest::addColumn<QString>("dialect");
    QTest::addColumn<QString>("firmware");
    QTest::addColumn<int>("baud");
    QTest::addColumn<double>("arrivesAt");
    QTest::addColumn<QPointF>("parks");
    QTest::newRow("K3NG GS-232B") << "gs232b" << "k3ng" << 9600 << 42.0 << QPointF(2, 90);
    QTest::newRow("K3NG Easycom") << "easycomm2" << "k3ng" << 9600 << 42.3 << QPointF(2.3, 90);
    QTest::newRow("SatNOGS") << "satnogs" << "satnogs" << 19200 << 40.0 << QPointF(0, 0);
}

void HeadlessTest::servesTheFirmwareInTheField()
{
    QFETCH(QString, dialect);
    QFETCH(QString, firmware);
    QFETCH(int, baud);
    QFETCH(double, arrivesAt);
    QFETCH(QPointF, parks);
    QTemporaryDir dir;
    const QString pty = dir.filePath("controller"), received = dir.filePath("received.log");
    SlewSimProcess sim;
    QVERIFY2(sim.start({"--pty", pty, "--dialect", dialect, "--firmware", firmware, "--baud", QString::number(baud),
                        "--time-scale", "10", "--model", "satnogs", "--start-az", "100", "--start-el", "10",
                        "--log-received", received}),
             qPrintable(sim.error()));
    QProcess slew;
    quint16 port = 0;
    QVERIFY2(startSlew(slew, {"--connect", QStringLiteral("serial:%1?baud=%2&dialect=%3&firmware=%4").arg(pty).arg(baud).arg(dialect, firmware),
                               "--rotctld-listen", "127.0.0.1:0"},
                       &port),
             slew.readAllStandardError().constData());
    const QString where = QStringLiteral("127.0.0.1:%1").arg(port);
    auto positionIs = [&](double az, double el) {
        QPointF at(qQNaN(), qQNaN());
        const bool there = QTest::qWaitFor([&] {
            const RotctlResult r = runRotctl({"-m", "2", "-r", where, "p"});
            const QList<QByteArray> lines = r.out.trimmed().split('\n');
            if (r.exitCode == 0 && lines.size() == 2)
                at = QPointF(lines[0].toDouble(), lines[1].toDouble());
            return std::abs(at.x() - az) < 0.15 && std::abs(at.y() - el) < 0.15;
        }, 30000);
        if (!there)
            qWarning("at %.2f, %.2f, not %.2f, %.2f", at.x(), at.y(), az, el);
        return there;
    };
    QVERIFY(positionIs(100, 10));
    QCOMPARE(runRotctl({"-m", "2", "-r", where, "P", "40", "25"}).exitCode, 0);
    QVERIFY(positionIs(arrivesAt, 25));
    QCOMPARE(runRotctl({"-m", "2", "-r", where, "S"}).exitCode, 0);
    QCOMPARE(runRotctl({"-m", "2", "-r", where, "K"}).exitCode, 0);
    QVERIFY(positionIs(parks.x(), parks.y()));
    // SIGTERM: the stop reaches the controller before the service goes,
    // though the SatNOGS firmware's turn-around may hold it a moment.
    auto stops = [&] {
        QFile f(received);
        return f.open(QIODevice::ReadOnly) ? f.readAll().count(dialect.startsWith("gs232") ? "\nS\n" : "SA SE\n") : -1;
    };
    const qsizetype before = stops();
    QSignalSpy finished(&slew, &QProcess::finished);
    ::kill(pid_t(slew.processId()), SIGTERM);
    QVERIFY(finished.wait(10000));
    QCOMPARE(slew.exitCode(), 0);
    QTRY_VERIFY_WITH_TIMEOUT(stops() > before, 5000);
    QCOMPARE(sim.stop(), 0);
    // The SatNOGS firmware loses what arrives in its turn-around: nothing did.
    QVERIFY2(sim.standardError().contains(" 0 bytes lost"), sim.standardError().constData());
}

void HeadlessTest::movesNothingItCannotRead()
{
    // K3NG's GS-232B emulation, and the service told Easycomm: no reply it
    // reads. Hamlib's rotctl gets an error for p and for P, the service's
    // log says why, and no move reaches the controller.
    QTemporaryDir dir;
    const QString pty = dir.filePath("controller"), received = dir.filePath("received.log");
    SlewSimProcess sim;
    QVERIFY2(sim.start({"--pty", pty, "--dialect", "gs232b", "--firmware", "k3ng", "--model", "satnogs", "--log-received",
                        received}),
             qPrintable(sim.error()));
    QProcess slew;
    quint16 port = 0;
    QVERIFY2(startSlew(slew, {"--connect", QStringLiteral("serial:%1?dialect=easycomm2").arg(pty), "--rotctld-listen",
                               "127.0.0.1:0"},
                       &port),
             slew.readAllStandardError().constData());
    const QString where = QStringLiteral("127.0.0.1:%1").arg(port);
    QByteArray said = m_startupLog;
    const QByteArray why = "no position read from the controller: check the dialect (easycomm2)";
    // The probe has given up on a position: from then on, the dialect is named.
    QVERIFY2(QTest::qWaitFor([&] {
        said += slew.readAllStandardOutput();
        return said.contains("still no position read");
    }, 30000), said.constData());
    QVERIFY(runRotctl({"-m", "2", "-r", where, "p"}).exitCode != 0);
    QVERIFY(runRotctl({"-m", "2", "-r", where, "P", "40", "25"}).exitCode != 0);
    QVERIFY2(QTest::qWaitFor([&] {
        said += slew.readAllStandardOutput();
        return said.contains(why);
    }, 10000), said.constData());
    QSignalSpy finished(&slew, &QProcess::finished);
    ::kill(pid_t(slew.processId()), SIGTERM);
    QVERIFY(finished.wait(10000));
    QCOMPARE(sim.stop(), 0);
    QFile log(received);
    QVERIFY(log.open(QIODevice::ReadOnly));
    const QByteArray heard = log.readAll();
    QVERIFY2(!heard.isEmpty() && !heard.contains("AZ40") && !heard.contains("W040"), heard.constData());
}
