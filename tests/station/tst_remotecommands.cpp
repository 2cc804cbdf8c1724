// SPDX-License-Identifier: GPL-3.0-or-later
// Commands from the broker obeyed under the Station's rules, with no broker:
// the station's command handler fed JSON as it would arrive, on the built-in
// simulator. The gate's own words for a move out of the travel; the
// operator's Stop holding remote moves off until control is handed back;
// Slew's own tracking holding them off too; Stop always obeyed, over the
// flood limit too; a jog that stops by itself when its lease is not renewed,
// and a renewal that sends nothing new to the rotator.

#include "../common/simulatorpump.h"
#include "linkschemes.h"

#include "remote/remotecommand.h"
#include "session/rotatorsession.h"
#include "station/remotecommands.h"
#include "station/remotejog.h"
#include "station/station.h"
#include "tracking/passrunner.h"
#include "tracking/tracktarget.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>

using slew::remote::RemoteReply;
using slew::station::RemoteCommands;
using slew::station::Station;
using slew::station::StationOptions;

namespace {

// On the simulator's manual clock (pumped: simulated seconds in wall
// milliseconds), or on the wall clock where a lease's real time matters.
StationOptions onTheSimulator(bool manualClock = true)
{
    StationOptions options;
    slew::model::RotatorProfile profile;
    profile.uri = manualClock ? QStringLiteral("sim:?model=satnogs&clock=manual&start_az=10&start_el=10")
                              : QStringLiteral("sim:?start_az=100&start_el=10");
    options.profile = profile;
    return options;
}

bool connectAndWait(Station &station, SimulatorPump &pump)
{
    slew::session::RotatorSession *rotor = station.session();
    pump.follow(rotor);
    station.connectRotators();
    return runEventLoopUntil([&] { return rotor->capabilities().probed && rotor->hasPosition(); }, 10000);
}

RemoteReply answer(RemoteCommands &commands, const QByteArray &json)
{
    return commands.handle(json).value_or(RemoteReply{QStringLiteral("none"), false, QStringLiteral("no reply")});
}

} // namespace

class RemoteCommandsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { slew::registerLinkSchemes(); }

    void movesPassTheGateInItsOwnWords()
    {
        Station station(onTheSimulator());
        SimulatorPump pump;
        QVERIFY(connectAndWait(station, pump));
        RemoteCommands commands(&station, {});
        slew::session::RotatorSession *rotor = station.session();
        const QString gate = rotor->moveGate().pointing(999, 30, rotor->azimuth()).refusal;
        QVERIFY(!gate.isEmpty());
        QSignalSpy sent(rotor, &slew::session::RotatorSession::moveSent);
        const RemoteReply refused = answer(commands, R"j({"id":"8","cmd":"goto","az":999,"el":30})j");
        QCOMPARE(refused.id, QStringLiteral("8"));
        QVERIFY(!refused.ok);
        QCOMPARE(refused.error, gate);
        QCOMPARE(sent.size(), 0);
        const RemoteReply ok = answer(commands, R"j({"id":"9","cmd":"goto","az":40,"el":20})j");
        QVERIFY2(ok.ok, qPrintable(ok.error));
        TRY_VERIFY_WITH_TIMEOUT(std::abs(rotor->azimuth() - 40) < 0.5 && std::abs(rotor->elevation() - 20) < 0.5, 20000);
        // A command without an id is obeyed and not answered.
        QVERIFY(!commands.handle(R"j({"cmd":"park"})j"));
    }

    void theOperatorsStopHoldsRemoteMovesOff()
    {
        Station station(onTheSimulator());
        SimulatorPump pump;
        QVERIFY(connectAndWait(station, pump));
        RemoteCommands commands(&station, {});
        QVERIFY(station.stop(QStringLiteral("the test")));
        QVERIFY(station.operatorHolds());
        const RemoteReply held = answer(commands, R"j({"id":"1","cmd":"goto","az":40,"el":20})j");
        QVERIFY(!held.ok);
        QVERIFY2(held.error.contains(QStringLiteral("holds remote control")), qPrintable(held.error));
        QVERIFY(!answer(commands, R"j({"id":"2","cmd":"jog","az_speed":5})j").ok);
        QVERIFY(!answer(commands, R"j({"id":"3","cmd":"park"})j").ok);
        // Stop is always obeyed.
        QSignalSpy stops(station.session(), &slew::session::RotatorSession::stopSent);
        QVERIFY(answer(commands, R"j({"id":"4","cmd":"stop"})j").ok);
        QCOMPARE(stops.size(), 1);
        QCOMPARE(stops.first().at(0).toString(), QStringLiteral("a stop over MQTT")); // what the logs say asked
        station.handControlBack();
        QVERIFY(answer(commands, R"j({"id":"5","cmd":"goto","az":40,"el":20})j").ok);
    }

    void slewsOwnTrackingHoldsRemoteMovesOff()
    {
        Station station(onTheSimulator());
        SimulatorPump pump;
        QVERIFY(connectAndWait(station, pump));
        RemoteCommands commands(&station, {});
        station.setPlace(slew::sky::Site{55.7, 12.6, 10, {}, {}});
        QVERIFY(answer(commands, R"j({"id":"t","cmd":"track","target":"azel:200,40"})j").ok);
        TRY_VERIFY_WITH_TIMEOUT(station.passRunner()->holdsRotator(), 20000);
        const RemoteReply held = answer(commands, R"j({"id":"g","cmd":"goto","az":40,"el":20})j");
        QVERIFY(!held.ok);
        QVERIFY2(held.error.contains(QStringLiteral("Slew's own tracking")), qPrintable(held.error));
        QVERIFY(answer(commands, R"j({"id":"u","cmd":"untrack"})j").ok);
        QVERIFY(!station.passRunner()->isRunning());
        QVERIFY(answer(commands, R"j({"id":"g2","cmd":"goto","az":40,"el":20})j").ok);
        // A satellite it has no elements for is refused, saying so.
        const RemoteReply unknown = answer(commands, R"j({"id":"s","cmd":"track","target":"NO SUCH SAT"})j");
        QVERIFY(!unknown.ok);
        QVERIFY2(unknown.error.contains(QStringLiteral("NO SUCH SAT")), qPrintable(unknown.error));
    }

    void aJogIsALease()
    {
        Station station(onTheSimulator(false));
        SimulatorPump pump;
        QVERIFY(connectAndWait(station, pump));
        RemoteCommands commands(&station, {});
        slew::session::RotatorSession *rotor = station.session();
        QSignalSpy moves(rotor, &slew::session::RotatorSession::moveSent);
        QSignalSpy stops(rotor, &slew::session::RotatorSession::stopSent);
        QSignalSpy expired(commands.jog(), &slew::station::RemoteJog::expired);
        QVERIFY(answer(commands, R"j({"id":"1","cmd":"jog","az_speed":10,"lease_ms":300})j").ok);
        QVERIFY(commands.jog()->isActive());
        const int sentFirst = moves.size();
        QVERIFY(sentFirst >= 1);
        // Renewed at the same speed: the lease goes on, nothing new is sent.
        QVERIFY(answer(commands, R"j({"id":"2","cmd":"jog","az_speed":10,"lease_ms":300})j").ok);
        QCOMPARE(moves.size(), sentFirst);
        QCOMPARE(stops.size(), 0);
        // Not renewed: stopped by itself.
        QVERIFY(expired.wait(3000));
        QCOMPARE(stops.size(), 1);
        QCOMPARE(stops.first().at(0).toString(), QStringLiteral("a remote jog's lease of 300 ms ran out"));
        QVERIFY(!commands.jog()->isActive());
        // Another command ends a lease without a stop of its own.
        QVERIFY(answer(commands, R"j({"id":"3","cmd":"jog","az_speed":-10,"lease_ms":1000})j").ok);
        QVERIFY(answer(commands, R"j({"id":"4","cmd":"goto","az":30,"el":10})j").ok);
        QVERIFY(!commands.jog()->isActive());
        QVERIFY(!expired.wait(1300));
    }

    void stopGetsThroughAFlood()
    {
        Station station(onTheSimulator());
        SimulatorPump pump;
        QVERIFY(connectAndWait(station, pump));
        RemoteCommands commands(&station, {});
        QSignalSpy logged(&commands, &RemoteCommands::logLine);
        int answered = 0;
        for (int i = 0; i < 100; ++i)
            answered += commands.handle(QStringLiteral(R"j({"id":"%1","cmd":"home"})j").arg(i).toUtf8()).has_value();
        QVERIFY(answered <= int(RemoteCommands::kBurst) + 1);
        QCOMPARE(commands.commandsDropped(), 100 - answered);
        QSignalSpy stops(station.session(), &slew::session::RotatorSession::stopSent);
        QVERIFY(!commands.handle(R"j({"id":"s","cmd":"stop"})j")); // dropped unanswered...
        QCOMPARE(stops.size(), 1);                                 // ...but obeyed
        int floods = 0;
        for (const QList<QVariant> &line : std::as_const(logged))
            floods += line.at(0).toString().contains(QStringLiteral("arriving faster"));
        QCOMPARE(floods, 1);
        QVERIFY(logged.wait(3000)); // the flood's end, with its count
        QVERIFY2(logged.last().at(0).toString().contains(QStringLiteral("dropped")), qPrintable(logged.last().at(0).toString()));
    }
};

QTEST_GUILESS_MAIN(RemoteCommandsTest)
#include "tst_remotecommands.moc"
