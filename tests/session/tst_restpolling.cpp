// SPDX-License-Identifier: GPL-3.0-or-later
// A quiet station: with nothing moving and nobody asking, the session polls
// the rotator at the profile's rest rate (1 Hz by default) instead of the
// full one, and goes back to the full rate at once on any command, on an
// alarm, and on motion seen in a reply. The stale alarm keeps the slow
// rate's time, and a link that dies at rest is still noticed.
//
// Every case runs a manual-clock simulator through the event loop and
// counts the position queries the session writes over a stretch of its time.

#include "../common/simulatorpump.h"
#include "linkschemes.h"
#include "protocol/encoder.h"
#include "session/rotatorsession.h"
#include "sim/simulator.h"
#include "sim/simulatorconnection.h"
#include "sim/simulatorlink.h"
#include "sim/simulatorscheme.h"

#include <QSignalSpy>
#include <QTest>

using namespace slew;
using session::RotatorSession;

namespace {

enum class Command { GoTo, Jog, Stop, Park, Home, RawLine, ReadRegister };

} // namespace

Q_DECLARE_METATYPE(Command)

class RestPollingTest : public QObject {
    Q_OBJECT
    // Longer than the quiet spell after which the session slows down
    // (PollPace::kQuietMs, 5 s), with a margin.
    static constexpr double kSettleSeconds = 7.0;
    // Motion smaller than this is jitter to the pace (PollPace::kMovedDegrees).
    static constexpr double kJitterDegrees = 0.05;

private slots:
    void initTestCase() { registerLinkSchemes(); }

    void slowsDownWhenNothingHappens();
    void aCommandWakesItAtOnce_data();
    void aCommandWakesItAtOnce();
    void motionSeenInAPositionWakesIt();
    void aMovingStatusWakesIt();
    void anAlarmWakesIt();
    void noFalseStaleAlarmAtTheRestRate();
    void aDeadLinkIsStillNoticedAtRest();

private:
    // A session on a manual-clock simulator, probed and positioned, with a
    // pump moving the simulator's clock on as the event loop turns.
    static bool open(RotatorSession &s, const model::RotatorProfile &profile = {})
    {
        s.setProfile(profile);
        s.connectTo(QStringLiteral("sim:?clock=manual"));
        (new SimulatorPump(0.005, &s))->follow(&s);
        return runEventLoopUntil([&] { return s.capabilities().probed && s.hasPosition(); }, 10000);
    }
    static sim::Simulator *simulatorOf(RotatorSession &s) { return sim::simulatorBehind(s.link()); }
    // Runs the session's (simulated) clock on by this many seconds.
    static bool runFor(RotatorSession &s, double seconds)
    {
        sim::Simulator *sim = simulatorOf(s);
        const double until = sim->clock().now() + seconds;
        return runEventLoopUntil([&] { return sim->clock().now() >= until; }, 60000);
    }
    // The position queries written over the next `seconds` of the session's clock.
    static int pollsIn(RotatorSession &s, double seconds)
    {
        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        if (!runFor(s, seconds))
            return -1;
        const QByteArray query = protocol::encodeQueryPosition(s.profile().dialect, 0);
        int n = 0;
        for (const auto &args : sent)
            n += args.at(0).toByteArray() == query ? 1 : 0;
        return n;
    }
    // Left alone long enough to rest, and seen resting: about one poll a second.
    static bool restsAtOneHertz(RotatorSession &s)
    {
        if (!runFor(s, kSettleSeconds))
            return false;
        const int polls = pollsIn(s, 10.0);
        if (polls < 9 || polls > 11) {
            qWarning("%d polls in 10 s at rest, not 9..11", polls);
            return false;
        }
        return true;
    }
};

void RestPollingTest::slowsDownWhenNothingHappens()
{
    RotatorSession s;
    QVERIFY(open(s));
    // Just connected, the session polls at the profile's full 10 Hz...
    const int early = pollsIn(s, 2.0);
    QVERIFY2(early >= 18, qPrintable(QString::number(early)));
    // ... and once nothing has moved and nobody has asked for a while, once a second.
    QVERIFY(runFor(s, kSettleSeconds));
    const int resting = pollsIn(s, 20.0);
    QVERIFY2(resting >= 19 && resting <= 21, qPrintable(QString::number(resting)));
    QCOMPARE(s.pollIntervalMs(), 100); // the full rate is still the profile's
}

void RestPollingTest::aCommandWakesItAtOnce_data()
{
    QTest::addColumn<Command>("command");
    QTest::newRow("go-to") << Command::GoTo;
    QTest::newRow("jog") << Command::Jog;
    QTest::newRow("stop") << Command::Stop;
    QTest::newRow("park") << Command::Park;
    QTest::newRow("home") << Command::Home;
    QTest::newRow("raw line") << Command::RawLine;
    QTest::newRow("read a register") << Command::ReadRegister;
}

void RestPollingTest::aCommandWakesItAtOnce()
{
    QFETCH(Command, command);
    RotatorSession s;
    QVERIFY(open(s));
    QVERIFY(restsAtOneHertz(s));
    session::CommandResult result;
    switch (command) {
    case Command::GoTo: result = s.gotoPosition(s.azimuth() + 10.0, s.elevation() + 5.0); break;
    case Command::Jog: result = s.moveAxis(session::Axis::Azimuth, 2.0); break;
    case Command::Stop: result = s.stop(QStringLiteral("the test")); break;
    case Command::Park: result = s.park(); break;
    case Command::Home: result = s.home(); break;
    case Command::RawLine: result = s.sendRaw(QStringLiteral("VE")); break;
    case Command::ReadRegister: result = s.readConfig(1); break;
    }
    QVERIFY2(result, qPrintable(result.refusal));
    // The full rate from the moment of the command, not from the next slow poll.
    const int woken = pollsIn(s, 1.0);
    QVERIFY2(woken >= 9, qPrintable(QString::number(woken)));
    // Whatever the command did, the station rests again once it is over
    // (a jog is stopped first: it runs until told otherwise).
    if (command == Command::Jog)
        QVERIFY(s.stop(QStringLiteral("the test")));
    QVERIFY(runFor(s, 30.0));
    QVERIFY(restsAtOneHertz(s));
}

void RestPollingTest::motionSeenInAPositionWakesIt()
{
    RotatorSession s;
    QVERIFY(open(s));
    QVERIFY(restsAtOneHertz(s));
    // Turned behind the session's back, as from the controller's own front
    // panel: the next slow poll sees it move, and the polling speeds up.
    sim::Simulator *sim = simulatorOf(s);
    sim->syncToNow();
    QVERIFY(sim->rotator().pointAzimuth(sim->rotator().axis(sim::Axis::Azimuth).position() + 30.0));
    QVERIFY(runFor(s, 1.2));
    const int woken = pollsIn(s, 1.0);
    QVERIFY2(woken >= 9, qPrintable(QString::number(woken)));
}

void RestPollingTest::aMovingStatusWakesIt()
{
    RotatorSession s;
    QVERIFY(open(s));
    QVERIFY(restsAtOneHertz(s));
    // Driven so slowly (a thousandth of a degree a second) that the
    // position hardly changes: the controller's status says it moves, and
    // the status is read with the telemetry, every tenth poll.
    sim::Simulator *sim = simulatorOf(s);
    sim->syncToNow();
    const double before = s.azimuth();
    sim->rotator().driveAzimuth(1.0);
    QVERIFY(runFor(s, 11.0));
    QVERIFY(std::abs(s.azimuth() - before) < kJitterDegrees);
    QVERIFY(s.status().anyMoving());
    const int woken = pollsIn(s, 1.0);
    QVERIFY2(woken >= 9, qPrintable(QString::number(woken)));
}

void RestPollingTest::anAlarmWakesIt()
{
    RotatorSession s;
    QVERIFY(open(s));
    QVERIFY(restsAtOneHertz(s));
    // The controller speaks up by itself: whatever follows an alarm is
    // watched closely.
    QSignalSpy alarms(&s, &RotatorSession::alarmReceived);
    auto *link = qobject_cast<sim::SimulatorLink *>(s.link());
    QVERIFY(link && link->connection());
    link->connection()->device()->write("ALmotor:overheated\n");
    QVERIFY(runEventLoopUntil([&] { return !alarms.isEmpty(); }, 10000));
    const int woken = pollsIn(s, 1.0);
    QVERIFY2(woken >= 9, qPrintable(QString::number(woken)));
}

void RestPollingTest::noFalseStaleAlarmAtTheRestRate()
{
    RotatorSession s;
    QVERIFY(open(s));
    QVERIFY(restsAtOneHertz(s));
    // A position a second is fresh enough at rest: a minute of it raises
    // no stale alarm.
    QSignalSpy positions(&s, &RotatorSession::positionChanged);
    QVERIFY(runFor(s, 60.0));
    QVERIFY(positions.count() >= 55);
    for (const auto &args : positions)
        QVERIFY(!args.at(2).toBool());
    QVERIFY(!s.positionStale());
}

void RestPollingTest::aDeadLinkIsStillNoticedAtRest()
{
    RotatorSession s;
    QVERIFY(open(s));
    QVERIFY(restsAtOneHertz(s));
    // The controller goes silent: the slow polls go unanswered, and the
    // position is stale within a few slow polls.
    sim::LinkFaults silent;
    silent.dropRate = 1.0;
    simulatorOf(s)->setLinkFaults(silent);
    QSignalSpy positions(&s, &RotatorSession::positionChanged);
    QVERIFY(runFor(s, 6.0));
    QVERIFY(s.positionStale());
    QVERIFY(!positions.isEmpty() && positions.last().at(2).toBool());
}

QTEST_MAIN(RestPollingTest)
#include "tst_restpolling.moc"
