// SPDX-License-Identifier: GPL-3.0-or-later
// The rotctld:// link: Slew reaching a rotator through a running rotctld.
// Against Hamlib's real rotctld: model 1 (its dummy rotator) and model 202
// (Easycomm II) on slew-sim's pseudo-terminal; and against Slew's own
// rotctld server, whose refusals come back as readable messages.

#include "../sim/slewsimprocess.h"
#include "bridge/rotctldserver.h"
#include "../common/hamlibprocess.h"
#include "linkschemes.h"
#include "session/rotatorsession.h"

#include <QTemporaryDir>
#include <QTest>

using namespace slew;

class RotctldLinkTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void againstHamlibDummy();
    void againstHamlibEasycommOnTheSimulator();
    void refusalsBecomeReadableMessages();
    void lostRotctldIsALoss();
    void badUri();

private:
    // Starts rotctld with the arguments on a free port; returns the port.
    quint16 startRotctld(QProcess &p, const QStringList &arguments);
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

void RotctldLinkTest::againstHamlibDummy()
{
    QProcess rotctld;
    const quint16 port = startRotctld(rotctld, {"-m", "1"});
    QVERIFY(port);
    session::RotatorSession s;
    model::RotatorProfile p;
    p.dialect = protocol::Dialect::SatNogs;
    s.setProfile(p);
    s.connectTo(QStringLiteral("rotctld://127.0.0.1:%1").arg(port));
    QTRY_VERIFY_WITH_TIMEOUT(s.isConnected() && s.capabilities().probed, 15000);
    // The limits come from \dump_state; the dummy says -180..450, 0..90.
    QVERIFY(s.reportedLimits());
    QCOMPARE(s.reportedLimits()->azMin, -180.0);
    QCOMPARE(s.reportedLimits()->azMax, 450.0);
    // Position and version work; what rotctld cannot give is absent.
    QVERIFY(s.capabilities().positionFeedback);
    QVERIFY(s.capabilities().version);
    QVERIFY(!s.capabilities().status);
    QVERIFY(!s.capabilities().config);
    QCOMPARE(s.version(), QStringLiteral("Dummy_rotator"));
    QTRY_VERIFY(s.hasPosition());
    QVERIFY(s.gotoPosition(20, 10));
    QTRY_VERIFY_WITH_TIMEOUT(std::abs(s.azimuth() - 20) < 0.5 && std::abs(s.elevation() - 10) < 0.5, 30000);
    // One axis: rotctld sets both, so the other is sent where it is going.
    // An elevation-only move was once remembered and never sent.
    QVERIFY(s.gotoAxis(session::Axis::Elevation, 25));
    QTRY_VERIFY_WITH_TIMEOUT(std::abs(s.elevation() - 25) < 0.5, 30000);
    QVERIFY(std::abs(s.azimuth() - 20) < 0.5);
    QVERIFY(s.gotoAxis(session::Axis::Azimuth, 30));
    QTRY_VERIFY_WITH_TIMEOUT(std::abs(s.azimuth() - 30) < 0.5, 30000);
    QVERIFY(std::abs(s.elevation() - 25) < 0.5);
    QVERIFY(s.stop());
    QVERIFY(s.park());
    QVERIFY(s.moveAxis(session::Axis::Azimuth, 2.0));
    QVERIFY(s.stop());
    s.disconnectFromRotator();
    rotctld.terminate();
    QTRY_COMPARE(rotctld.state(), QProcess::NotRunning);
}

void RotctldLinkTest::againstHamlibEasycommOnTheSimulator()
{
    QTemporaryDir dir;
    const QString pty = dir.filePath("rotator");
    SlewSimProcess sim;
    QVERIFY2(sim.start({"--model", "satnogs", "--pty", pty, "--dialect", "easycomm2", "--log-received",
                        dir.filePath("received.log")}),
             qPrintable(sim.error()));
    QProcess rotctld;
    const quint16 port = startRotctld(rotctld, {"-m", "202", "-r", pty, "-s", "19200"});
    QVERIFY(port);
    session::RotatorSession s;
    s.connectTo(QStringLiteral("rotctld://127.0.0.1:%1").arg(port));
    QTRY_VERIFY_WITH_TIMEOUT(s.isConnected() && s.hasPosition(), 15000);
    QVERIFY(s.gotoPosition(45, 30));
    QTRY_VERIFY_WITH_TIMEOUT(std::abs(s.azimuth() - 45) < 0.5 && std::abs(s.elevation() - 30) < 0.5, 30000);
    QVERIFY(s.stop());
    // The simulator heard Hamlib's Easycomm II bytes for our commands.
    auto received = [&] {
        QFile log(dir.filePath("received.log"));
        return log.open(QIODevice::ReadOnly) ? log.readAll() : QByteArray();
    };
    QTRY_VERIFY2(received().contains("AZ45.0 EL30.0"), received().right(300).constData());
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
    s.connectTo(QStringLiteral("rotctld://127.0.0.1:%1").arg(server.port()));
    QTRY_VERIFY_WITH_TIMEOUT(s.isConnected() && s.hasPosition(), 15000);
    QVERIFY(s.gotoPosition(100, 20));
    QTRY_VERIFY(!errors.isEmpty());
    const QString message = errors.last().at(0).toString();
    QVERIFY2(message.contains("command rejected") && message.contains("RPRT -9") && message.contains("P 100.00 20.00"),
             qPrintable(message));
}

void RotctldLinkTest::lostRotctldIsALoss()
{
    QProcess rotctld;
    const quint16 port = startRotctld(rotctld, {"-m", "1"});
    QVERIFY(port);
    session::RotatorSession s;
    s.connectTo(QStringLiteral("rotctld://127.0.0.1:%1").arg(port));
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
