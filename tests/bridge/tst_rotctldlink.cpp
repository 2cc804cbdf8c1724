// SPDX-License-Identifier: GPL-3.0-or-later
// The rotctld:// link: Slew reaching a rotator through a running rotctld,
// the session speaking the rotctld dialect straight to it. Against Hamlib's
// real rotctld: model 1 (its dummy rotator) and model 202 (Easycomm II) on
// slew-sim's pseudo-terminal; and against Slew's own rotctld server, whose
// refusals come back as readable messages.

#include "../sim/slewsimprocess.h"
#include "bridge/rotctldserver.h"
#include "../common/hamlibprocess.h"
#include "linkschemes.h"
#include "protocol/dialect.h"
#include "session/rotatorsession.h"
#include "transport/linkfactory.h"

#include <QTemporaryDir>
#include <QTest>

using namespace slew;

class RotctldLinkTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void theLinkNamesItsDialect();
    void againstHamlibDummy();
    void oneAxisMovesReachRotctld();
    void againstHamlibEasycommOnTheSimulator();
    void refusalsBecomeReadableMessages();
    void lostRotctldIsALoss();
    void badUri();

private:
    // Starts rotctld with the arguments on a free port; returns the port.
    quint16 startRotctld(QProcess &p, const QStringList &arguments);
    // A session with the rotctld dialect, connected to the port.
    static void connectSession(session::RotatorSession &s, quint16 port);
};

void RotctldLinkTest::initTestCase()
{
    registerLinkSchemes();
    QVERIFY2(!hamlibProgram("rotctld").isEmpty(), "rotctld is not installed: packaging/dev.sh installs libhamlib-utils");
}

quint16 RotctldLinkTest::startRotctld(QProcess &p, const QStringList &arguments)
{
    const quint16 port = freeTcpPort();
    p.setProgram(hamlibProgram("rotctld"));
    p.setArguments(arguments + QStringList{"-T", "127.0.0.1", "-t", QString::number(port)});
    p.start();
    // Ready when it accepts a connection.
    const bool up = QTest::qWaitFor(
        [&] {
            QTcpSocket probe;
            QSignalSpy connected(&probe, &QTcpSocket::connected);
            probe.connectToHost(QHostAddress::LocalHost, port);
            return connected.wait(200);
        },
        10000);
    return up ? port : 0;
}

void RotctldLinkTest::connectSession(session::RotatorSession &s, quint16 port)
{
    model::RotatorProfile p;
    p.dialect = protocol::Dialect::Rotctld;
    s.setProfile(p);
    s.connectTo(QStringLiteral("rotctld://127.0.0.1:%1").arg(port));
}

// Where rotctld itself says the rotator is, asked on a connection of its
// own: what reached rotctld, not what the session believes.
static std::optional<std::pair<double, double>> rotctldPosition(quint16 port)
{
    QTcpSocket client;
    QSignalSpy connected(&client, &QTcpSocket::connected);
    client.connectToHost(QHostAddress::LocalHost, port);
    if (!connected.wait(5000))
        return std::nullopt;
    client.write("p\n");
    QByteArray answer;
    QSignalSpy readable(&client, &QTcpSocket::readyRead);
    while (answer.count('\n') < 2 && readable.wait(5000))
        answer += client.readAll();
    const QList<QByteArray> lines = answer.split('\n');
    if (lines.size() < 2)
        return std::nullopt;
    bool okAz = false, okEl = false;
    const double az = lines[0].toDouble(&okAz), el = lines[1].toDouble(&okEl);
    client.write("q\n");
    if (!okAz || !okEl)
        return std::nullopt;
    return std::pair{az, el};
}

void RotctldLinkTest::theLinkNamesItsDialect()
{
    // The window takes the dialect from the link's hints, before connecting.
    QCOMPARE(transport::linkHintsFor(QStringLiteral("rotctld://127.0.0.1:4533")).dialect, QStringLiteral("rotctld"));
}

void RotctldLinkTest::againstHamlibDummy()
{
    QProcess rotctld;
    const quint16 port = startRotctld(rotctld, {"-m", "1"});
    QVERIFY(port);
    session::RotatorSession s;
    QSignalSpy sent(&s, &session::RotatorSession::bytesSent);
    connectSession(s, port);
    QTRY_VERIFY_WITH_TIMEOUT(s.isConnected() && s.capabilities().probed, 15000);
    // The limits come from \dump_state; the dummy says -180..450, 0..90.
    QVERIFY(s.reportedLimits());
    QCOMPARE(s.reportedLimits()->azMin, -180.0);
    QCOMPARE(s.reportedLimits()->azMax, 450.0);
    // Position and the model's name come from p and _; what rotctld has no
    // command for is not asked, and absent.
    QVERIFY(s.capabilities().positionFeedback);
    QVERIFY(s.capabilities().version);
    QVERIFY(!s.capabilities().status);
    QVERIFY(!s.capabilities().config);
    QVERIFY(!s.capabilities().velocity);
    QVERIFY(s.capabilities().moveCommands);
    QCOMPARE(s.version(), QStringLiteral("Dummy rotator"));
    QTRY_VERIFY(s.hasPosition());
    // Near targets: Hamlib's dummy turns at 6°/s.
    QVERIFY(s.gotoPosition(6, 3));
    QTRY_VERIFY_WITH_TIMEOUT(std::abs(s.azimuth() - 6) < 0.5 && std::abs(s.elevation() - 3) < 0.5, 30000);
    QVERIFY(s.stop(QStringLiteral("the test")));
    QVERIFY(s.park());
    QVERIFY(s.home());
    QVERIFY(s.moveAxis(session::Axis::Azimuth, 2.0));
    QVERIFY(s.stop(QStringLiteral("the test")));
    // What went on the wire is rotctld's own commands, nothing else.
    QByteArray wire;
    for (const QList<QVariant> &args : std::as_const(sent))
        wire += args.at(0).toByteArray();
    for (const char *command : {"p\n", "_\n", "P 6.00 3.00\n", "S\n", "K\n", "R 1\n", "M 16 50\n"})
        QVERIFY2(wire.contains(command), wire.constData());
    QVERIFY2(!wire.contains("AZ") && !wire.contains("GS") && !wire.contains("CR"), wire.constData());
    s.disconnectFromRotator();
    rotctld.terminate();
    QTRY_COMPARE(rotctld.state(), QProcess::NotRunning);
}

void RotctldLinkTest::oneAxisMovesReachRotctld()
{
    QProcess rotctld;
    const quint16 port = startRotctld(rotctld, {"-m", "1"});
    QVERIFY(port);
    session::RotatorSession s;
    QSignalSpy sent(&s, &session::RotatorSession::bytesSent);
    connectSession(s, port);
    QTRY_VERIFY_WITH_TIMEOUT(s.isConnected() && s.hasPosition(), 15000);
    // Near targets: Hamlib's dummy turns at 6°/s.
    QVERIFY(s.gotoPosition(6, 3));
    QTRY_VERIFY_WITH_TIMEOUT(std::abs(s.azimuth() - 6) < 0.5 && std::abs(s.elevation() - 3) < 0.5, 30000);
    // rotctld's P takes both axes: an elevation-only move sends the azimuth
    // where it was going. It once was remembered and never sent.
    sent.clear();
    QVERIFY(s.gotoAxis(session::Axis::Elevation, 8));
    QCOMPARE(sent.count(), 1);
    QCOMPARE(sent.at(0).at(0).toByteArray(), QByteArray("P 6.00 8.00\n"));
    QTRY_VERIFY_WITH_TIMEOUT(std::abs(s.elevation() - 8) < 0.5, 30000);
    // rotctld itself, asked on a connection of its own, is there.
    // (No answer reads as NaN, which no comparison below accepts.)
    const std::pair<double, double> noAnswer{qQNaN(), qQNaN()};
    std::pair<double, double> there = noAnswer;
    QTRY_VERIFY_WITH_TIMEOUT((there = rotctldPosition(port).value_or(noAnswer), std::abs(there.second - 8) < 0.5), 30000);
    QVERIFY2(std::abs(there.first - 6) < 0.5, qPrintable(QString::number(there.first)));
    // And azimuth alone keeps the elevation.
    QVERIFY(s.gotoAxis(session::Axis::Azimuth, 10));
    QTRY_VERIFY_WITH_TIMEOUT((there = rotctldPosition(port).value_or(noAnswer), std::abs(there.first - 10) < 0.5), 30000);
    QVERIFY(std::abs(there.second - 8) < 0.5);
    // A one-axis move outside rotctld's limits stops at the gate.
    sent.clear();
    QVERIFY(!s.gotoAxis(session::Axis::Elevation, 95));
    QCOMPARE(sent.count(), 0);
    s.disconnectFromRotator();
    rotctld.terminate();
    QTRY_COMPARE(rotctld.state(), QProcess::NotRunning);
}

void RotctldLinkTest::againstHamlibEasycommOnTheSimulator()
{
    QTemporaryDir dir;
    const QString pty = dir.filePath("rotator");
    SlewSimProcess sim;
    QVERIFY2(sim.start({"--model", "satnogs", "--time-scale", "4", "--pty", pty, "--dialect", "easycomm2", "--log-received",
                        dir.filePath("received.log")}),
             qPrintable(sim.error()));
    QProcess rotctld;
    const quint16 port = startRotctld(rotctld, {"-m", "202", "-r", pty, "-s", "19200"});
    QVERIFY(port);
    session::RotatorSession s;
    connectSession(s, port);
    QTRY_VERIFY_WITH_TIMEOUT(s.isConnected() && s.hasPosition(), 15000);
    QVERIFY(s.gotoPosition(45, 30));
    QTRY_VERIFY_WITH_TIMEOUT(std::abs(s.azimuth() - 45) < 0.5 && std::abs(s.elevation() - 30) < 0.5, 30000);
    // The simulator heard Hamlib's Easycomm II bytes for our commands.
    auto received = [&] {
        QFile log(dir.filePath("received.log"));
        return log.open(QIODevice::ReadOnly) ? log.readAll() : QByteArray();
    };
    QTRY_VERIFY2(received().contains("AZ45.0 EL30.0"), received().right(300).constData());
    // An elevation-only move reaches the controller too, the azimuth going
    // on to where it was sent.
    QVERIFY(s.gotoAxis(session::Axis::Elevation, 20));
    QTRY_VERIFY2(received().contains("AZ45.0 EL20.0"), received().right(300).constData());
    QTRY_VERIFY_WITH_TIMEOUT(std::abs(s.elevation() - 20) < 0.5, 30000);
    QVERIFY(s.stop(QStringLiteral("the test")));
    QTRY_VERIFY2(received().contains("SA SE"), received().right(300).constData());
    s.disconnectFromRotator();
    rotctld.terminate();
    QTRY_COMPARE(rotctld.state(), QProcess::NotRunning);
}

void RotctldLinkTest::refusalsBecomeReadableMessages()
{
    // Slew's own server, in front of the simulator, with the operator holding control.
    session::RotatorSession behind;
    behind.connectTo("sim:");
    QTRY_VERIFY(behind.isConnected() && behind.hasPosition());
    bridge::RotctldServer server(&behind);
    QString error;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0, &error));
    server.holdRemote();

    session::RotatorSession s;
    QSignalSpy errors(&s, &session::RotatorSession::errorOccurred);
    QSignalSpy alarms(&s, &session::RotatorSession::alarmReceived);
    connectSession(s, server.port());
    QTRY_VERIFY_WITH_TIMEOUT(s.isConnected() && s.hasPosition(), 15000);
    QVERIFY(s.gotoPosition(100, 20));
    QVERIFY(s.activeTarget());
    QTRY_VERIFY(!alarms.isEmpty());
    const QString message = errors.last().at(0).toString();
    QVERIFY2(message.contains("command rejected") && message.contains("RPRT -9") && message.contains("RIG_ERJCTED"),
             qPrintable(message));
    // Refused: the target is not where the rotator is going, so a tracker's
    // next repeat of it goes out again.
    QVERIFY(!s.activeTarget());
}

void RotctldLinkTest::lostRotctldIsALoss()
{
    QProcess rotctld;
    const quint16 port = startRotctld(rotctld, {"-m", "1"});
    QVERIFY(port);
    session::RotatorSession s;
    connectSession(s, port);
    QTRY_VERIFY_WITH_TIMEOUT(s.isConnected(), 15000);
    QSignalSpy states(&s, &session::RotatorSession::stateChanged);
    rotctld.kill();
    QTRY_COMPARE_WITH_TIMEOUT(s.state(), session::RotatorSession::State::Disconnected, 10000);
    QVERIFY(states.last().at(1).toString().contains(QStringLiteral("rotctld://127.0.0.1:%1").arg(port)));
}

void RotctldLinkTest::badUri()
{
    session::RotatorSession s;
    QSignalSpy errors(&s, &session::RotatorSession::errorOccurred);
    s.connectTo("rotctld://");
    QVERIFY(errors.last().at(0).toString().contains("no host"));
    const quint16 port = freeTcpPort();
    s.connectTo(QStringLiteral("rotctld://127.0.0.1:%1").arg(port));
    QTRY_COMPARE(s.state(), session::RotatorSession::State::Disconnected);
    QVERIFY(errors.last().at(0).toString().contains("refused", Qt::CaseInsensitive));
}

QTEST_GUILESS_MAIN(RotctldLinkTest)
#include "tst_rotctldlink.moc"
