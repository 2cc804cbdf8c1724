// SPDX-License-Identifier: GPL-3.0-or-later
// Commands from the broker obeyed under the Station's rules, with no broker:
// the station's command handler fed JSON as it would arrive, on the built-in
// simulator. The gate's own words for a move out of the travel; the
// operator's Stop holding remote moves off until control is handed back;
// Slew's own tracking holding them off too; Stop always obeyed, over the
// flood limit too; a jog that stops by itself when its lease is not renewed,
// and a renewal that sends nothing new to the rotator; a schedule held off
// as a track is, its end and the radio's hold not.

#include "../common/simulatorpump.h"
#include "linkschemes.h"

#include "remote/remotecommand.h"
#include "session/rotatorsession.h"
#include "sky/elementsetformat.h"
#include "face/stationface.h"
#include "station/alarmmonitor.h"
#include "station/dopplerradio.h"
#include "station/remotecommands.h"
#include "station/remotejog.h"
#include "station/schedulerunner.h"
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
    return commands.handle(json).value_or(RemoteReply{QStringLiteral("none"), false, QStringLiteral("no reply"), std::nullopt});
}

} // namespace

class RemoteCommandsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        slew::registerLinkSchemes();
        qRegisterMetaType<RemoteReply>();
    }

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

    // A jammed azimuth on a controller that reports nothing (GS-232B): the
    // motion guard stops and holds it, the state says so and the alarm
    // names it; a remote go-to is refused with why; clear_fault frees it.
    void theMotionGuardsHoldIsClearedFromAfar()
    {
        slew::station::StationOptions options;
        slew::model::RotatorProfile profile;
        // The simulator's own motor error never comes: silent, as a GS-232 is.
        profile.uri = QStringLiteral("sim:?clock=manual&dialect=gs232b&start_az=10&start_el=10&jam=az&jam_after=600");
        profile.dialect = slew::protocol::Dialect::Gs232B;
        options.profile = profile;
        Station station(options);
        SimulatorPump pump;
        QVERIFY(connectAndWait(station, pump));
        RemoteCommands commands(&station, {});
        QCOMPARE(answer(commands, R"j({"id":"0","cmd":"clear_fault"})j").error, QStringLiteral("no axis is held by the motion guard"));
        QCOMPARE(station.face()->clearMotionFaults().reason(), QStringLiteral("no axis is held by the motion guard"));
        QVERIFY(answer(commands, R"j({"id":"1","cmd":"goto","az":120,"el":30})j").ok);
        TRY_VERIFY_WITH_TIMEOUT(station.session()->hasMotionFault(), 20000);
        QVERIFY(station.face()->state()->motionHeld);
        const QStringList alarms = station.alarms()->activeAlarms();
        QVERIFY2(alarms.size() == 1 && alarms.first().startsWith(QStringLiteral("Azimuth did not move for 5"))
                     && alarms.first().endsWith(QStringLiteral("moves of it are held until the fault is cleared")),
                 qPrintable(alarms.join(u'\n')));
        const RemoteReply held = answer(commands, R"j({"id":"2","cmd":"goto","az":100,"el":30})j");
        QVERIFY(!held.ok);
        QVERIFY2(held.error.startsWith(QStringLiteral("the azimuth is held after the motion guard stopped it")), qPrintable(held.error));
        QVERIFY(answer(commands, R"j({"id":"3","cmd":"clear_fault"})j").ok);
        QVERIFY(!station.session()->hasMotionFault());
        QVERIFY(!station.face()->state()->motionHeld);
        // The guard's alarm is gone (the refused go-to's warning stays its 10 s).
        QVERIFY(station.alarms()->activeAlarms().filter(QStringLiteral("until the fault is cleared")).isEmpty());
    }

    // A schedule's preview moves nothing, so no hold refuses it; it is
    // answered later, when planned, with each target named.
    void aPreviewIsAnsweredWhenPlannedUnderAnyHold()
    {
        Station station(onTheSimulator());
        SimulatorPump pump;
        QVERIFY(connectAndWait(station, pump));
        station.setPlace(slew::sky::Site{55.7, 12.6, 10, {}, {}});
        RemoteCommands commands(&station, {});
        QVERIFY(station.stop(QStringLiteral("the test")));
        QVERIFY(station.operatorHolds());
        QSignalSpy late(&commands, &RemoteCommands::lateReply);
        QSignalSpy moves(station.session(), &slew::session::RotatorSession::moveSent);
        QVERIFY(!commands.handle(R"j({"id":"p1","cmd":"schedule_preview","targets":["sun","NO SUCH SATELLITE"],"hours":6})j"));
        TRY_VERIFY_WITH_TIMEOUT(late.size() == 1, 20000);
        const RemoteReply reply = late.first().at(0).value<RemoteReply>();
        QCOMPARE(reply.id, QStringLiteral("p1"));
        QVERIFY2(reply.ok && reply.preview, qPrintable(reply.error));
        QCOMPARE(reply.preview->targets.size(), 2);
        QCOMPARE(reply.preview->targets[0].name, QStringLiteral("the sun"));
        QVERIFY(!reply.preview->targets[1].isFound());
        QCOMPARE(reply.preview->schedule.targets, QStringList{QStringLiteral("the sun")});
        QCOMPARE(moves.size(), 0);
        QVERIFY(!station.scheduleRunner()->isRunning());
        // Without an id there is no one to answer: refused, said as a fault.
        QVERIFY(!commands.handle(R"j({"cmd":"schedule_preview","targets":["sun"]})j"));
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

    void aScheduleIsAMoveAndEndingOneIsNot()
    {
        Station station(onTheSimulator());
        SimulatorPump pump;
        QVERIFY(connectAndWait(station, pump));
        station.setPlace(slew::sky::Site{55.7, 12.6, 10, {}, {}});
        // Satellites the station was given (the service's --tle).
        const slew::sky::ElementSetFile given =
            slew::sky::readElementSetFile(QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle"));
        QVERIFY(!given.sets.isEmpty());
        RemoteCommands commands(&station, given.sets);
        slew::station::ScheduleRunner *schedule = station.scheduleRunner();

        // A name that finds nothing refuses the whole schedule, naming it.
        const RemoteReply unknown = answer(commands, R"j({"id":"1","cmd":"schedule","targets":["FLOCK 2P-1","NO SUCH SAT"]})j");
        QVERIFY(!unknown.ok);
        QVERIFY2(unknown.error.contains(QStringLiteral("NO SUCH SAT")), qPrintable(unknown.error));
        QVERIFY(!schedule->isRunning());
        // So does one that finds several.
        const RemoteReply several = answer(commands, R"j({"id":"2","cmd":"schedule","targets":["FLOCK 2P"]})j");
        QVERIFY(!several.ok);
        QVERIFY2(several.error.contains(QStringLiteral("'FLOCK 2P' matches")), qPrintable(several.error));
        // An empty list is the station's to refuse, in its own words.
        QCOMPARE(answer(commands, R"j({"id":"3","cmd":"schedule","targets":[]})j").error,
                 QStringLiteral("a schedule needs at least one target"));

        // Two satellites, by name and by catalogue number, with the
        // operator's numbers: run, and planned with them.
        const RemoteReply ran = answer(
            commands, R"j({"id":"4","cmd":"schedule","targets":["FLOCK 2P-1","40039"],"hours":12,"min_el":5,"guard_s":60})j");
        QVERIFY2(ran.ok, qPrintable(ran.error));
        QVERIFY(schedule->isRunning());
        QCOMPARE(schedule->targets().size(), 2);
        QCOMPARE(schedule->targets().at(1).name(), QStringLiteral("PERSEUS-M1"));
        TRY_VERIFY_WITH_TIMEOUT(schedule->schedule().settings.startJulian > 0, 20000);
        QCOMPARE(schedule->schedule().settings.hours, 12.0);
        QCOMPARE(schedule->schedule().settings.minElevationDeg, 5.0);
        QCOMPARE(schedule->schedule().settings.guardSeconds, 60.0);

        // Ended from afar; a second time there is none to end.
        QVERIFY(answer(commands, R"j({"id":"5","cmd":"unschedule"})j").ok);
        QVERIFY(!schedule->isRunning());
        QCOMPARE(answer(commands, R"j({"id":"6","cmd":"unschedule"})j").error, QStringLiteral("no schedule is running"));

        // The operator's hold refuses a schedule as it refuses a track...
        QVERIFY(station.stop(QStringLiteral("the test")));
        const RemoteReply held = answer(commands, R"j({"id":"7","cmd":"schedule","targets":["FLOCK 2P-1"]})j");
        QVERIFY(!held.ok);
        QVERIFY2(held.error.contains(QStringLiteral("holds remote control")), qPrintable(held.error));
        QVERIFY(!schedule->isRunning());
        // ...but not its end: the operator's own schedule may be ended from afar.
        QVERIFY(station.runSchedule({schedule->targets().first()}, slew::station::ScheduleOptions{}).isDone());
        QVERIFY(answer(commands, R"j({"id":"8","cmd":"unschedule"})j").ok);
        QVERIFY(!schedule->isRunning());
        station.handControlBack();

        // Slew's own tracking holds a schedule off as it holds a go-to off.
        QVERIFY(answer(commands, R"j({"id":"9","cmd":"track","target":"azel:200,40"})j").ok);
        TRY_VERIFY_WITH_TIMEOUT(station.passRunner()->holdsRotator(), 20000);
        const RemoteReply tracking = answer(commands, R"j({"id":"10","cmd":"schedule","targets":["FLOCK 2P-1"]})j");
        QVERIFY(!tracking.ok);
        QVERIFY2(tracking.error.contains(QStringLiteral("Slew's own tracking")), qPrintable(tracking.error));
        // Unschedule ends a schedule only: one target tracked is untrack's.
        QCOMPARE(answer(commands, R"j({"id":"11","cmd":"unschedule"})j").error, QStringLiteral("no schedule is running"));
        QVERIFY(station.passRunner()->isRunning());
        QVERIFY(answer(commands, R"j({"id":"12","cmd":"untrack"})j").ok);

        // A station that is closing starts nothing, and ends nothing either
        // but by Stop.
        commands.refuseFromNow(QStringLiteral("the station is shutting down"));
        QCOMPARE(answer(commands, R"j({"id":"13","cmd":"schedule","targets":["FLOCK 2P-1"]})j").error,
                 QStringLiteral("the station is shutting down"));
        QCOMPARE(answer(commands, R"j({"id":"14","cmd":"unschedule"})j").error,
                 QStringLiteral("the station is shutting down"));
    }

    // The radio's hold is no move of the rotator: Slew's tracking does not
    // hold it off (one takes the dial during a pass), and taking the dial
    // is always obeyed, as a stop is; handing it back to the Doppler
    // steering waits for the operator at the station to hand control back.
    void theRadiosHoldIsNotAMove()
    {
        Station station(onTheSimulator());
        SimulatorPump pump;
        QVERIFY(connectAndWait(station, pump));
        station.setPlace(slew::sky::Site{55.7, 12.6, 10, {}, {}});
        RemoteCommands commands(&station, {});
        slew::station::DopplerRadio *radio = station.radio();
        QVERIFY(radio->linkUri().isEmpty()); // no radio set: the hold is kept for one set later
        QSignalSpy held(radio, &slew::station::DopplerRadio::controlHeldChanged);
        QVERIFY(answer(commands, R"j({"id":"1","cmd":"radio_hold","held":true})j").ok);
        QVERIFY(radio->isControlHeld());
        QCOMPARE(held.size(), 1);
        QVERIFY(answer(commands, R"j({"id":"2","cmd":"radio_hold","held":false})j").ok);
        QVERIFY(!radio->isControlHeld());

        QVERIFY(answer(commands, R"j({"id":"3","cmd":"track","target":"azel:200,40"})j").ok);
        TRY_VERIFY_WITH_TIMEOUT(station.passRunner()->holdsRotator(), 20000);
        QVERIFY(answer(commands, R"j({"id":"4","cmd":"radio_hold","held":true})j").ok);
        QVERIFY(radio->isControlHeld());
        QVERIFY(answer(commands, R"j({"id":"5","cmd":"radio_hold","held":false})j").ok);
        QVERIFY(!radio->isControlHeld());
        QVERIFY(station.passRunner()->isRunning()); // the tracking went on

        QVERIFY(station.stop(QStringLiteral("the test")));
        QVERIFY(answer(commands, R"j({"id":"6","cmd":"radio_hold","held":true})j").ok);
        QVERIFY(radio->isControlHeld());
        const RemoteReply back = answer(commands, R"j({"id":"7","cmd":"radio_hold","held":false})j");
        QVERIFY(!back.ok);
        QVERIFY2(back.error.contains(QStringLiteral("holds remote control")), qPrintable(back.error));
        QVERIFY(radio->isControlHeld());
        station.handControlBack();
        QVERIFY(answer(commands, R"j({"id":"8","cmd":"radio_hold","held":false})j").ok);
        QVERIFY(!radio->isControlHeld());

        commands.refuseFromNow(QStringLiteral("the station is shutting down"));
        QCOMPARE(answer(commands, R"j({"id":"9","cmd":"radio_hold","held":true})j").error,
                 QStringLiteral("the station is shutting down"));
        QVERIFY(!radio->isControlHeld());
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
