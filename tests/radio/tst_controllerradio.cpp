// SPDX-License-Identifier: GPL-3.0-or-later
// The radio behind the rotator controller: Doppler-corrected `DN`/`UP`
// through the rotator session to slew-sim, a real process on TCP, whose
// record of what it received shows the frequencies; and its answers to
// `DN`/`UP` read back through the same link. Easycomm I takes the
// settings blind. And the contract every radio link keeps
// (radiolinkcontract.h), over a session on the simulator in process.

#include "../common/simulatorpump.h"
#include "../sim/slewsimprocess.h"
#include "linkschemes.h"
#include "radiolinkcontract.h"
#include "radio/controllerradio.h"
#include "radio/dopplersteering.h"
#include "session/rotatorsession.h"

#include <QElapsedTimer>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using slew::radio::ControllerRadioLink;
using slew::radio::DopplerSteering;
using slew::radio::RadioLink;
using slew::session::RotatorSession;

namespace {

std::optional<double> approaching(double julian)
{
    return -6.0 + 12.0 * (julian * 86400.0) / 600.0; // km/s, over ten minutes
}

// A session on the in-process simulator (Easycomm II, which answers
// DN/UP), connected, with its clock pumped by the event loop.
bool connectToSimulator(RotatorSession &session)
{
    slew::model::RotatorProfile profile;
    profile.dialect = slew::protocol::Dialect::Easycomm2;
    session.setProfile(profile);
    session.connectTo(QStringLiteral("sim:?clock=manual&dialect=easycomm2"));
    (new SimulatorPump(0.005, &session))->follow(&session);
    return runEventLoopUntil([&] { return session.isConnected() && session.capabilities().probed; }, 10000);
}

} // namespace

class ControllerRadioTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { slew::registerLinkSchemes(); }

    void steersThroughSlewSim()
    {
        QTemporaryDir dir;
        const QString received = dir.filePath("received.log");
        SlewSimProcess sim;
        QVERIFY2(sim.start({"--listen", "127.0.0.1:0", "--dialect", "easycomm2", "--log-received", received}),
                 qPrintable(sim.error()));
        RotatorSession session;
        slew::model::RotatorProfile profile;
        profile.dialect = slew::protocol::Dialect::Easycomm2;
        session.setProfile(profile);
        session.connectTo(QStringLiteral("tcp://127.0.0.1:%1").arg(sim.port()));
        QVERIFY(runEventLoopUntil([&] { return session.isConnected() && session.capabilities().probed; }, 10000));

        ControllerRadioLink radio(&session);
        QSignalSpy state(&radio, &RadioLink::stateChanged);
        radio.open();
        QCOMPARE(radio.state(), RadioLink::State::Open);
        QVERIFY(!radio.canReadBack()); // what it answers is what it was told: no dial to follow

        DopplerSteering steering(&radio);
        slew::radio::SatelliteFrequencies sat;
        sat.downlinkHz = 435.15e6;
        sat.uplinkHz = 145.95e6;
        steering.begin(sat, approaching);
        // Four seconds on the wall clock (slew-sim is a real process on
        // real time), a step every 20 ms, the event loop turning between.
        QElapsedTimer wall;
        wall.start();
        qint64 ms = 0;
        while ((ms = wall.elapsed()) < 4000) {
            steering.step(ms / 86400000.0, ms);
            runEventLoopUntil([] { return false; }, 20);
        }
        QVERIFY2(steering.commandsSent() > 40, qPrintable(QString::number(steering.commandsSent())));
        QVERIFY(!steering.dialTurning()); // its own values read back are not a dial
        const double lastDown = *steering.sentReceiveHz(), lastUp = *steering.sentTransmitHz();

        // slew-sim's record has the last frequencies sent, as the tables write them.
        auto record = [&] {
            QFile f(received);
            return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        };
        const QByteArray down = "DN" + QByteArray::number(qint64(lastDown));
        const QByteArray up = "UP" + QByteArray::number(qint64(lastUp));
        QVERIFY2(runEventLoopUntil([&] { return record().contains(down) && record().contains(up); }, 5000),
                 (down + " " + up).constData());
        // Both are Doppler-corrected: approaching at about 5.9 km/s by then,
        // the Doppler moving 29 Hz a second on the downlink.
        const slew::radio::RadioTuning expected = slew::radio::tuningFor(sat, *approaching(ms / 86400000.0));
        QVERIFY2(std::abs(lastDown - expected.receiveHz) < 30, qPrintable(QString::number(lastDown - expected.receiveHz)));
        QVERIFY2(std::abs(lastUp - *expected.transmitHz) < 30, qPrintable(QString::number(lastUp - *expected.transmitHz)));

        // And slew-sim answers DN/UP with what it holds.
        QSignalSpy read(&radio, &RadioLink::frequenciesRead);
        radio.readFrequencies();
        QVERIFY(read.wait(5000));
        const auto held = read.last().at(0).value<slew::radio::RadioFrequencies>();
        QCOMPARE(*held.receiveHz, lastDown);
        QCOMPARE(*held.transmitHz, lastUp);

        // Each path's mode on its own line: an inverting linear
        // transponder takes LSB up and gives USB down.
        radio.setMode("USB", 0);
        radio.setTransmitMode("LSB", 0);
        QVERIFY(runEventLoopUntil([&] { return record().contains("DMUSB") && record().contains("UMLSB"); }, 5000));
        session.disconnectFromRotator();
    }

    void contract_data() { radiolinkcontract::addContractRows(); }
    void contract()
    {
        QFETCH(QString, check);
        RotatorSession session;
        QVERIFY(connectToSimulator(session));
        ControllerRadioLink link(&session);
        // Its settings have no answer, and UP is a path of its own: read always.
        radiolinkcontract::checkEveryLinkContract(check, {link, link.pacer(), false, true});
    }

    // What the shared limits allow but the controller's lines cannot carry
    // (ten digits of hertz, a mode of eight characters) is refused in words
    // when given, and never reaches the wire; what they carry goes.
    void refusesWhatItsLinesCannotCarry()
    {
        RotatorSession session;
        QVERIFY(connectToSimulator(session));
        ControllerRadioLink radio(&session);
        radio.open();
        QTRY_VERIFY(!radio.pacer().isBusy()); // the opening's reading is in
        QSignalSpy failed(&radio, &RadioLink::commandFailed);
        QSignalSpy bytes(&session, &RotatorSession::bytesSent);
        radio.setReceiveHz(2e10);
        radio.setTransmitHz(9999999999.6); // eleven digits once rounded
        radio.setMode("PKTUSBWIDE", 0);
        radio.setTransmitMode("PKTLSBWIDE", 0);
        QCOMPARE(radiolinkcontract::texts(failed, 0),
                 (QStringList{"DN20000000000", "UP10000000000", "DMPKTUSBWIDE", "UMPKTLSBWIDE"}));
        QCOMPARE(radiolinkcontract::texts(failed, 1),
                 (QStringList{"not sent: the controller's DN line carries at most ten digits of hertz (9999999999 Hz)",
                              "not sent: the controller's UP line carries at most ten digits of hertz (9999999999 Hz)",
                              "not sent: the controller's DM line carries a mode of at most 8 letters or digits",
                              "not sent: the controller's UM line carries a mode of at most 8 letters or digits"}));
        radio.setReceiveHz(9999999999);
        radio.setMode("PKTUSB", 0);
        QCOMPARE(failed.count(), 4);
        QByteArray wire;
        for (const auto &args : bytes)
            wire += args.at(0).toByteArray();
        QVERIFY2(wire.contains("DN9999999999") && wire.contains("DMPKTUSB"), wire.constData());
        QVERIFY2(!wire.contains("DN2") && !wire.contains("UP1") && !wire.contains("WIDE"), wire.constData());
    }

    void easycommOneIsSteeredBlind()
    {
        RotatorSession session;
        slew::model::RotatorProfile profile;
        profile.dialect = slew::protocol::Dialect::Easycomm1;
        session.setProfile(profile);
        session.connectTo(QStringLiteral("sim:?clock=manual&dialect=easycomm1"));
        (new SimulatorPump(0.005, &session))->follow(&session);
        QVERIFY(runEventLoopUntil([&] { return session.isConnected(); }, 10000));
        ControllerRadioLink radio(&session);
        radio.open();
        QCOMPARE(radio.state(), RadioLink::State::Open);
        QSignalSpy sent(&session, &RotatorSession::bytesSent);
        DopplerSteering steering(&radio);
        slew::radio::SatelliteFrequencies sat;
        sat.downlinkHz = 437.8e6;
        steering.begin(sat, approaching);
        for (qint64 ms = 0; ms <= 5000; ms += 20) {
            steering.step(ms / 86400000.0, ms);
            QCoreApplication::processEvents();
        }
        // Nothing waits for a reading: the downlink keeps up.
        QVERIFY(steering.commandsSent() > 5);
        bool sawDown = false;
        for (const auto &args : sent)
            sawDown = sawDown || args.at(0).toByteArray().startsWith("DN");
        QVERIFY(sawDown);
    }

    void aRotatorWithoutStationCommandsHasNoRadioBehindIt()
    {
        RotatorSession session;
        slew::model::RotatorProfile profile;
        profile.dialect = slew::protocol::Dialect::Gs232B;
        session.setProfile(profile);
        session.connectTo(QStringLiteral("sim:?clock=manual&dialect=gs232b"));
        (new SimulatorPump(0.005, &session))->follow(&session);
        QVERIFY(runEventLoopUntil([&] { return session.isConnected(); }, 10000));
        ControllerRadioLink radio(&session);
        QSignalSpy state(&radio, &RadioLink::stateChanged);
        radio.open();
        QCOMPARE(radio.state(), RadioLink::State::Closed);
        QVERIFY2(state.last().at(1).toString().contains(QStringLiteral("no station radio commands")),
                 qPrintable(state.last().at(1).toString()));
        // A setting on the closed link is refused in words, as every radio
        // link refuses, and nothing reaches the wire.
        QSignalSpy failed(&radio, &RadioLink::commandFailed);
        QSignalSpy sent(&session, &RotatorSession::bytesSent);
        radio.setReceiveHz(437.8e6);
        radio.setMode(QStringLiteral("FM"), 0);
        QCOMPARE(failed.size(), 2);
        QCOMPARE(failed.first().at(0).toString(), QStringLiteral("DN437800000"));
        QCOMPARE(failed.first().at(1).toString(), QStringLiteral("not sent: controller is not open"));
        for (const auto &args : sent)
            QVERIFY2(!args.at(0).toByteArray().startsWith("DN") && !args.at(0).toByteArray().startsWith("DM"),
                     args.at(0).toByteArray().constData());
    }
};

QTEST_GUILESS_MAIN(ControllerRadioTest)
#include "tst_controllerradio.moc"
