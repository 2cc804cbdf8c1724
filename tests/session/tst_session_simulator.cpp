// SPDX-License-Identifier: GPL-3.0-or-later
// RotatorSession against the real simulator on every kind of link it has:
// the in-process sim: link, slew-sim over TCP, and slew-sim's pseudo-terminal
// opened as a serial port (QSerialPort). Probe, polling, telemetry, config
// write then read-back, go-to, stop, park, home, and faults seen as errors.

#include "../common/simulatorpump.h"
#include "../sim/slewsimprocess.h"
#include "linkschemes.h"
#include "session/rotatorsession.h"
#include "sim/simulator.h"
#include "sim/simulatorscheme.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <optional>

using namespace slew;
using session::RotatorSession;

namespace {

// The value the session reported for a register, if any came: telemetry
// polls read CR10/CR11 in between, so the answer asked for is not always
// the last one to arrive.
std::optional<QString> valueFor(const QSignalSpy &values, int reg)
{
    for (auto it = values.crbegin(); it != values.crend(); ++it) {
        if (it->at(0).toInt() == reg)
            return it->at(1).toString();
    }
    return std::nullopt;
}

} // namespace

class SessionSimulatorTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { registerLinkSchemes(); }
    void probeFindsEverythingTheDerivativeHas();
    void configWriteThenReadBack();
    void gotoStopParkHome();
    void telemetryArrives();
    void jamShowsAsMotorError();
    void satnogsDialect();
    void easycomm2MovesWithMlMr();
    void gs232Dialects_data();
    void gs232Dialects();
    void overTcpToSlewSim();
    void overASerialPortToSlewSimsPty();

private:
    static SimulatorPump *pumpOf(RotatorSession &s)
    {
        for (QObject *child : s.children()) {
            if (auto *pump = dynamic_cast<SimulatorPump *>(child))
                return pump;
        }
        return nullptr;
    }
    static bool connectTo(RotatorSession &s, const QString &uri, protocol::Dialect d = protocol::Dialect::Easycomm3);
};

// The in-process simulator runs on its manual clock, pumped from the event
// loop: simulated seconds pass in wall milliseconds, and the session's own
// timers keep the simulator's time, so nothing depends on the machine's speed.
bool SessionSimulatorTest::connectTo(RotatorSession &s, const QString &uri_, protocol::Dialect d)
{
    QString uri = uri_;
    if (uri.startsWith(QLatin1String("sim:"))) {
        uri += uri.contains(u'?') ? QStringLiteral("&clock=manual") : QStringLiteral("?clock=manual");
        auto *pump = new SimulatorPump(0.005, &s);
        pump->follow(&s);
    }
    model::RotatorProfile p;
    p.uri = uri;
    p.dialect = d;
    s.setProfile(p);
    s.connectTo(uri);
    return runEventLoopUntil([&] { return s.isConnected() && s.capabilities().probed && s.hasPosition(); }, 15000);
}

void SessionSimulatorTest::probeFindsEverythingTheDerivativeHas()
{
    RotatorSession s;
    QVERIFY(connectTo(s, "sim:"));
    const auto c = s.capabilities();
    QVERIFY(c.positionFeedback && c.version && c.status && c.errors && c.inputs && c.config && c.encoders);
    QVERIFY(c.velocity && c.park && c.reset && c.stop);
    QCOMPARE(s.version(), QStringLiteral("SlewSim-1.0"));
    TRY_VERIFY(s.status().valid);
    TRY_COMPARE(s.errorFlags(), 1); // "no error" in the SatNOGS / the Easycomm III derivative reading
}

void SessionSimulatorTest::configWriteThenReadBack()
{
    RotatorSession s;
    QVERIFY(connectTo(s, "sim:"));
    QSignalSpy values(&s, &RotatorSession::configValueReceived);
    QVERIFY(s.writeConfig(1, "2.75"));
    QVERIFY(s.writeConfig(8, "45"));
    QVERIFY(s.readConfig(1));
    QVERIFY(s.readConfig(8));
    auto valueOf = [&](int reg) {
        for (const auto &v : values)
            if (v.at(0).toInt() == reg)
                return v.at(1).toString().toDouble();
        return qQNaN();
    };
    TRY_COMPARE(valueOf(1), 2.75);
    TRY_COMPARE(valueOf(8), 45.0);
}

void SessionSimulatorTest::gotoStopParkHome()
{
    RotatorSession s;
    QVERIFY(connectTo(s, "sim:?model=satnogs&park_az=90&park_el=10"));
    QVERIFY(s.gotoPosition(20, 15));
    TRY_VERIFY_WITH_TIMEOUT(std::abs(s.azimuth() - 20) < 0.2 && std::abs(s.elevation() - 15) < 0.2, 15000);
    QSignalSpy commanded(&s, &RotatorSession::commandedChanged);
    TRY_VERIFY(!commanded.isEmpty()); // CR10/CR11 polled back
    QCOMPARE(commanded.last().at(0).toDouble(), 20.0);

    // Simulated time runs far faster than the test looks, so a passing state
    // is caught as the session reports it; the clock is held there, so Stop
    // is pressed while the rotator is on its way.
    SimulatorPump *pump = pumpOf(s);
    QVERIFY(pump);
    bool sawMoving = false;
    auto holdWhenMoving = connect(&s, &RotatorSession::statusChanged, this, [&](session::StatusWord w) {
        if (w.anyMoving() && !sawMoving) {
            sawMoving = true;
            pump->pause();
        }
    });
    QVERIFY(s.gotoPosition(80, 40));
    TRY_VERIFY(sawMoving);
    QVERIFY(s.stop(QStringLiteral("the test")));
    pump->resume();
    TRY_VERIFY_WITH_TIMEOUT(s.status().idle(), 15000);
    QVERIFY(std::abs(s.azimuth() - 80) > 1); // stopped on the way
    disconnect(holdWhenMoving);

    QVERIFY(s.park());
    TRY_VERIFY_WITH_TIMEOUT(std::abs(s.azimuth() - 90) < 0.2 && std::abs(s.elevation() - 10) < 0.2, 15000);
    QSignalSpy statuses(&s, &RotatorSession::statusChanged);
    QVERIFY(s.home());
    TRY_VERIFY_WITH_TIMEOUT(std::any_of(statuses.cbegin(), statuses.cend(),
                                         [](const QList<QVariant> &a) {
                                             return a.at(0).value<session::StatusWord>().anyMoving();
                                         }),
                             5000);
    TRY_VERIFY_WITH_TIMEOUT(s.status().idle() && std::abs(s.azimuth()) < 0.2 && std::abs(s.elevation()) < 0.2, 30000);
}

void SessionSimulatorTest::telemetryArrives()
{
    RotatorSession s;
    QVERIFY(connectTo(s, "sim:"));
    QVERIFY(s.moveAxis(session::Axis::Azimuth, 5.0));
    TRY_VERIFY_WITH_TIMEOUT(s.telemetry().azVelocity > 1.0, 10000);
    QVERIFY(!std::isnan(s.telemetry().temperature));
    QVERIFY(!std::isnan(s.telemetry().azLoad));
    QVERIFY(s.telemetry().azEndStop >= 0);
    QVERIFY(s.stop(QStringLiteral("the test")));
    TRY_VERIFY_WITH_TIMEOUT(std::abs(s.telemetry().azVelocity) < 0.05, 10000);
}

void SessionSimulatorTest::jamShowsAsMotorError()
{
    RotatorSession s;
    QVERIFY(connectTo(s, "sim:?jam=az&jam_after=0.3"));
    QVERIFY(s.gotoPosition(60, 0));
    TRY_VERIFY_WITH_TIMEOUT(s.errorFlags() > 1 && (s.errorFlags() & session::ErrorMotor), 10000);
    TRY_VERIFY(s.status().anyError());
    QVERIFY(session::describeErrorFlags(s.errorFlags()).contains("motor"));
    // The simulator stays reachable behind the session's link (tests, the wizard).
    sim::Simulator *simulator = sim::simulatorBehind(s.link());
    QVERIFY(simulator);
    QVERIFY(s.stop(QStringLiteral("the test")));
}

void SessionSimulatorTest::satnogsDialect()
{
    RotatorSession s;
    QVERIFY(connectTo(s, "sim:?model=satnogs&dialect=satnogs", protocol::Dialect::SatNogs));
    QVERIFY(!s.capabilities().encoders); // not in SatNOGS
    QSignalSpy values(&s, &RotatorSession::configValueReceived);
    QSignalSpy sent(&s, &RotatorSession::bytesSent);
    QVERIFY(s.readConfig(4));
    TRY_VERIFY(valueFor(values, 4));
    bool spaced = false;
    for (const auto &b : sent)
        spaced = spaced || b.at(0).toByteArray() == "CR 4\n";
    QVERIFY(spaced);
    QVERIFY(s.gotoPosition(30, 30));
    TRY_VERIFY_WITH_TIMEOUT(std::abs(s.azimuth() - 30) < 0.2, 15000);
}

void SessionSimulatorTest::easycomm2MovesWithMlMr()
{
    RotatorSession s;
    QVERIFY(connectTo(s, "sim:?dialect=easycomm2", protocol::Dialect::Easycomm2));
    QVERIFY(!s.capabilities().status && !s.capabilities().config);
    const double start = s.azimuth();
    QSignalSpy sent(&s, &RotatorSession::bytesSent);
    QVERIFY(s.moveAxis(session::Axis::Azimuth, 3.0));
    TRY_VERIFY_WITH_TIMEOUT(s.azimuth() > start + 2, 10000);
    QVERIFY(s.stop(QStringLiteral("the test"), session::Axes::Azimuth));
    bool mr = false;
    for (const auto &b : sent)
        mr = mr || b.at(0).toByteArray() == "MR\n";
    QVERIFY(mr);
}

void SessionSimulatorTest::gs232Dialects_data()
{
    QTest::addColumn<QString>("name");
    QTest::newRow("gs232a") << "gs232a";
    QTest::newRow("gs232b") << "gs232b";
}

void SessionSimulatorTest::gs232Dialects()
{
    QFETCH(QString, name);
    const auto dialect = *protocol::dialectFromName(name);
    RotatorSession s;
    QVERIFY(connectTo(s, "sim:?model=satnogs&dialect=" + name, dialect));
    QVERIFY(s.capabilities().positionFeedback);
    // GS answered ST=n: the session reads the status as from Easycomm's GS.
    QVERIFY(s.capabilities().status);
    QVERIFY(!s.capabilities().errors && !s.capabilities().config && !s.capabilities().velocity);
    TRY_VERIFY(s.status().valid);
    QSignalSpy sent(&s, &RotatorSession::bytesSent);
    QSignalSpy status(&s, &RotatorSession::statusChanged);
    QVERIFY(s.gotoPosition(42, 17));
    TRY_VERIFY_WITH_TIMEOUT(std::abs(s.azimuth() - 42) < 0.6 && std::abs(s.elevation() - 17) < 0.6, 15000);
    TRY_VERIFY_WITH_TIMEOUT(!status.isEmpty(), 15000); // it moved: the status changed
    const double start = s.azimuth();
    QVERIFY(s.moveAxis(session::Axis::Azimuth, 3.0));
    TRY_VERIFY_WITH_TIMEOUT(s.azimuth() > start + 2, 10000);
    QVERIFY(s.stop(QStringLiteral("the test")));
    QStringList wire;
    for (const auto &b : sent)
        wire << QString::fromLatin1(b.at(0).toByteArray());
    QVERIFY2(wire.contains("W042 017\r") && wire.contains("C2\r") && wire.contains("R\r") && wire.contains("S\r")
                 && wire.contains("GS\r"),
             qPrintable(wire.join('|')));
    QVERIFY(!s.home()); // GS-232 has no homing command: refused, nothing sent
}

// The two slew-sim processes run at 4x: these check the link, not the slew.
void SessionSimulatorTest::overTcpToSlewSim()
{
    SlewSimProcess sim;
    QVERIFY2(sim.start({"--listen", "127.0.0.1:0", "--model", "satnogs", "--time-scale", "4"}), qPrintable(sim.error()));
    RotatorSession s;
    QVERIFY(connectTo(s, QStringLiteral("tcp://127.0.0.1:%1").arg(sim.port())));
    QVERIFY(s.capabilities().encoders);
    QVERIFY(s.gotoPosition(12.5, 7.25));
    TRY_VERIFY_WITH_TIMEOUT(std::abs(s.azimuth() - 12.5) < 0.2 && std::abs(s.elevation() - 7.25) < 0.2, 15000);
    QCOMPARE(sim.stop(), 0);
}

void SessionSimulatorTest::overASerialPortToSlewSimsPty()
{
    QTemporaryDir dir;
    const QString pty = dir.filePath("ttySLEW");
    SlewSimProcess sim;
    QVERIFY2(sim.start({"--pty", pty, "--baud", "19200", "--dialect", "satnogs", "--model", "satnogs", "--time-scale", "4"}), qPrintable(sim.error()));
    RotatorSession s;
    QVERIFY(connectTo(s, "serial:" + pty + "?baud=19200", protocol::Dialect::SatNogs));
    QVERIFY(s.capabilities().version);
    QVERIFY(s.gotoPosition(33, 22));
    TRY_VERIFY_WITH_TIMEOUT(std::abs(s.azimuth() - 33) < 0.2 && std::abs(s.elevation() - 22) < 0.2, 15000);
    QSignalSpy values(&s, &RotatorSession::configValueReceived);
    QVERIFY(s.writeConfig(2, "0.125"));
    QVERIFY(s.readConfig(2));
    TRY_VERIFY(valueFor(values, 2));
    QCOMPARE(valueFor(values, 2)->toDouble(), 0.125);
    QCOMPARE(sim.stop(), 0);
}

QTEST_GUILESS_MAIN(SessionSimulatorTest)
#include "tst_session_simulator.moc"
