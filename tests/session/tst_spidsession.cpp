// SPDX-License-Identifier: GPL-3.0-or-later
// The session speaking SPID's binary frames (Rot2Prog, Rot1Prog, MD-01/02)
// to the simulator's SPID firmware, on the manual clock: the probe and
// polls as status frames, a set written in the resolution the replies
// gave, stop, the jog (the MD-01's move command; a go-to the end of the
// travel on the others), the MD-01's log lines skipped, and polling slowed
// to the line's rate. Then the same against slew-sim as a real process on
// a pty, opened as a serial port at 600 baud.

#include "../common/simulatorpump.h"
#include "../sim/slewsimprocess.h"
#include "linkschemes.h"
#include "protocol/parser.h"
#include "protocol/spidcodec.h"
#include "session/rotatorsession.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using slew::protocol::Dialect;
using slew::session::Axes;
using slew::session::Axis;
using slew::session::RotatorSession;
namespace spid = slew::protocol::spid;

namespace {

bool open(RotatorSession &s, Dialect d, const QString &options, double azMax = 360, double elMax = 90)
{
    slew::model::RotatorProfile profile;
    profile.dialect = d;
    profile.limits = slew::model::RotatorLimits{0, azMax, 0, d == Dialect::Rot1Prog ? 0.0 : elMax};
    s.setProfile(profile);
    s.connectTo(QStringLiteral("sim:?clock=manual&model=satnogs&dialect=%1&%2")
                    .arg(slew::protocol::dialectName(d), options));
    (new SimulatorPump(0.01, &s))->follow(&s);
    return runEventLoopUntil([&] { return s.capabilities().probed && s.hasPosition(); }, 10000);
}

bool arrives(RotatorSession &s, double az, double el)
{
    return runEventLoopUntil([&] { return std::abs(s.azimuth() - az) < 0.3 && std::abs(s.elevation() - el) < 0.3; },
                             20000);
}

// The last set frame among the bytes sent, as the controller reads it.
std::optional<QPointF> setIn(const QSignalSpy &sent)
{
    std::optional<QPointF> last;
    slew::protocol::Parser parser(Dialect::Rot2Prog);
    std::optional<double> az;
    for (const QList<QVariant> &args : sent)
        parser.feed(args.at(0).toByteArray(), [&](const slew::protocol::Message &m) {
            if (m.op == slew::protocol::Op::Azimuth && m.hasValue)
                az = m.value;
            if (m.op == slew::protocol::Op::Elevation && m.hasValue && az)
                last = QPointF(*az, m.value);
        });
    return last;
}

QList<QByteArray> frames(const QSignalSpy &sent)
{
    QList<QByteArray> list;
    for (const QList<QVariant> &args : sent)
        list.append(args.at(0).toByteArray());
    return list;
}

} // namespace

class SpidSessionTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { slew::registerLinkSchemes(); }

    // What a Rot2Prog has, and what it lacks, as the probe finds it.
    void probesAndPollsWithStatusFrames()
    {
        RotatorSession s;
        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        QVERIFY(open(s, Dialect::Rot2Prog, QStringLiteral("start_az=100&start_el=20")));
        const auto &caps = s.capabilities();
        QVERIFY(caps.positionFeedback && caps.stop);
        QVERIFY(!caps.velocity && !caps.moveCommands && !caps.config && !caps.park && !caps.reset);
        QVERIFY(!caps.version && !caps.status && !caps.errors && !caps.inputs && !caps.encoders);
        QVERIFY(std::abs(s.azimuth() - 100) < 0.05 && std::abs(s.elevation() - 20) < 0.05);
        for (const QByteArray &f : frames(sent))
            QCOMPARE(f, spid::encodeStatus()); // nothing but status frames so far
        QVERIFY(sent.size() >= 1);
        // A typed text line would be garbage on a binary wire: refused.
        sent.clear();
        const auto raw = s.sendRaw(QStringLiteral("AZ10 EL10"));
        QVERIFY(!raw);
        QVERIFY2(raw.refusal.contains(QStringLiteral("binary frames")), qPrintable(raw.refusal));
        QVERIFY(frames(sent).isEmpty() || frames(sent) == QList<QByteArray>(sent.size(), spid::encodeStatus()));
    }

    // A set in the controller's pulses per degree: the simulator reports 2
    // unless told otherwise, and 4 here.
    void setsInTheResolutionTheRepliesGave_data()
    {
        QTest::addColumn<int>("pulses");
        QTest::newRow("2 pulses a degree") << 2;
        QTest::newRow("4 pulses a degree") << 4;
    }

    void setsInTheResolutionTheRepliesGave()
    {
        QFETCH(int, pulses);
        RotatorSession s;
        QVERIFY(open(s, Dialect::Rot2Prog, QStringLiteral("spid_pulses=%1").arg(pulses)));
        QCOMPARE(s.setResolutionDeg(), 1.0 / pulses);
        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        QVERIFY(s.gotoPosition(123.5, 41.25));
        QVERIFY(!sent.isEmpty());
        QCOMPARE(sent.first().at(0).toByteArray(), spid::encodeSet(123.5, 41.25, Dialect::Rot2Prog, pulses, pulses).bytes);
        QVERIFY(arrives(s, 123.5, 41.25));
        // The profile applied anew (the wizard does, page by page): the
        // resolution learnt is kept, and the next set goes out at once.
        s.setProfile(s.profile());
        sent.clear();
        QVERIFY(s.gotoPosition(100, 30));
        QCOMPARE(sent.first().at(0).toByteArray(), spid::encodeSet(100, 30, Dialect::Rot2Prog, pulses, pulses).bytes);
    }

    // The stop frame, and the worm-gear rotator stays where it stopped.
    void stopEndsAMove()
    {
        RotatorSession s;
        QVERIFY(open(s, Dialect::Rot2Prog, QStringLiteral("start_az=10&start_el=5")));
        QVERIFY(s.gotoPosition(300, 80));
        QVERIFY(runEventLoopUntil([&] { return s.azimuth() > 60; }, 20000));
        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        QSignalSpy stops(&s, &RotatorSession::stopSent);
        QVERIFY(s.stop(QStringLiteral("the test")));
        QCOMPARE(stops.size(), 1);
        QCOMPARE(sent.first().at(0).toByteArray(), spid::encodeStop());
        QVERIFY(runEventLoopUntil([&] { return !s.positionStale(); }, 5000));
        double before = s.azimuth();
        QVERIFY(runEventLoopUntil(
            [&] {
                const bool still = std::abs(s.azimuth() - before) < 0.05;
                before = s.azimuth();
                return still && s.azimuth() < 200;
            },
            10000));
        QVERIFY(!s.activeTarget());
    }

    // Rot2Prog has no speed or move command: a jog is a go-to the way the
    // operator pressed, in legs of under half a turn (a controller may take
    // 360° for north and turn the short way to it), each followed by the
    // next before it ends, up to the end of the travel; the release's stop
    // ends it. A second axis jogged meanwhile keeps the first running.
    void jogsInLegsOfUnderHalfATurn()
    {
        RotatorSession s;
        QVERIFY(open(s, Dialect::Rot2Prog, QStringLiteral("start_az=100&start_el=20&spid_pulses=1")));
        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        QVERIFY(s.moveAxis(Axis::Azimuth, 5.0));
        QCOMPARE(setIn(sent), QPointF(270, 20)); // 170° on, not 360°
        QVERIFY(!s.activeTarget()); // a jog, not a target of the operator's
        // Past the first leg's end: the next leg went out on the way.
        QVERIFY(runEventLoopUntil([&] { return s.azimuth() > 300; }, 20000));
        QCOMPARE(setIn(sent).value_or(QPointF()).x(), 360.0);
        sent.clear();
        QVERIFY(s.moveAxis(Axis::Elevation, -5.0));
        QCOMPARE(setIn(sent), QPointF(360, 0));
        // The elevation released: a stop (which halts both), and the azimuth goes on.
        sent.clear();
        QVERIFY(s.stop(QStringLiteral("the test"), Axes::Elevation));
        QCOMPARE(sent.first().at(0).toByteArray(), spid::encodeStop());
        QCOMPARE(setIn(sent).value_or(QPointF()).x(), 360.0);
        QVERIFY(runEventLoopUntil([&] { return s.azimuth() > 359.5; }, 20000));
        // At the end of the travel: refused, nothing sent.
        QSignalSpy refused(&s, &RotatorSession::moveRefused);
        sent.clear();
        QVERIFY(!s.moveAxis(Axis::Azimuth, 5.0));
        QCOMPARE(refused.size(), 1);
        QCOMPARE(setIn(sent), std::nullopt);
        QVERIFY(s.stop(QStringLiteral("the test")));
        // Anticlockwise from 100°: to 0°, which is the way pressed.
        RotatorSession back;
        QVERIFY(open(back, Dialect::Rot2Prog, QStringLiteral("start_az=100&start_el=20&spid_pulses=1")));
        QSignalSpy backSent(&back, &RotatorSession::bytesSent);
        QVERIFY(back.moveAxis(Axis::Azimuth, -5.0));
        QCOMPARE(setIn(backSent), QPointF(0, 20));
        QVERIFY(runEventLoopUntil([&] { return back.azimuth() < 90; }, 20000));
        QVERIFY(back.stop(QStringLiteral("the test")));
    }

    // The MD-01/02 has a move command: one frame names every running axis.
    void md01JogsWithItsMoveCommand()
    {
        namespace Bit = spid::MoveBit;
        RotatorSession s;
        QVERIFY(open(s, Dialect::Md01, QStringLiteral("start_az=100&start_el=20")));
        QVERIFY(s.capabilities().moveCommands);
        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        QVERIFY(s.moveAxis(Axis::Azimuth, -3.0));
        QCOMPARE(sent.last().at(0).toByteArray(), spid::encodeMove(Bit::Left, Dialect::Md01).bytes);
        QVERIFY(s.moveAxis(Axis::Elevation, 3.0));
        QCOMPARE(sent.last().at(0).toByteArray(), spid::encodeMove(Bit::Left | Bit::Up, Dialect::Md01).bytes);
        QVERIFY(runEventLoopUntil([&] { return s.azimuth() < 95 && s.elevation() > 25; }, 10000));
        sent.clear();
        QVERIFY(s.stop(QStringLiteral("the test"), Axes::Azimuth));
        QCOMPARE(frames(sent), (QList<QByteArray>{spid::encodeStop(), spid::encodeMove(Bit::Up, Dialect::Md01).bytes}));
        QVERIFY(s.stop(QStringLiteral("the test")));
    }

    // MD-01 firmware that logs text among its frames: skipped, said once,
    // and the position still read.
    void md01LogLinesAreSkipped()
    {
        RotatorSession s;
        QSignalSpy errors(&s, &RotatorSession::errorOccurred);
        QSignalSpy failed(&s, &RotatorSession::requestFailed);
        QVERIFY(open(s, Dialect::Md01, QStringLiteral("md01_log&start_az=50&start_el=10")));
        QVERIFY(s.gotoPosition(80, 30));
        QVERIFY(arrives(s, 80, 30));
        QVERIFY(s.textLinesSkipped() > 5);
        int said = 0;
        for (const QList<QVariant> &e : errors)
            said += e.at(0).toString().contains(QStringLiteral("writes text lines among its replies")) ? 1 : 0;
        QCOMPARE(said, 1);
        QCOMPARE(failed.size(), 0);
    }

    // Rot1Prog: azimuth only, in whole degrees.
    void rot1ProgTurnsAzimuthOnly()
    {
        RotatorSession s;
        QVERIFY(open(s, Dialect::Rot1Prog, QStringLiteral("start_az=30")));
        QVERIFY(s.isAzimuthOnly());
        QCOMPARE(s.elevation(), 0.0);
        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        QVERIFY(s.gotoPosition(211, 0));
        QCOMPARE(sent.first().at(0).toByteArray(), spid::encodeSet(211, 0, Dialect::Rot1Prog).bytes);
        QVERIFY(arrives(s, 211, 0));
        QVERIFY(!s.gotoPosition(211, 10)); // no elevation to command
    }

    // Before the first reply there is no resolution: a set is refused
    // rather than guessed (a Rot2Prog at 2 pulses a degree would go to
    // twice the angle).
    void noSetBeforeTheResolutionIsKnown()
    {
        RotatorSession s;
        slew::model::RotatorProfile profile;
        profile.dialect = Dialect::Rot2Prog;
        s.setProfile(profile);
        std::optional<slew::session::CommandResult> early;
        connect(&s, &RotatorSession::stateChanged, &s, [&](RotatorSession::State state) {
            if (state == RotatorSession::State::Connected && !early)
                early = s.gotoPosition(50, 10);
        });
        s.connectTo(QStringLiteral("sim:?clock=manual&dialect=rot2prog"));
        (new SimulatorPump(0.01, &s))->follow(&s);
        QVERIFY(runEventLoopUntil([&] { return early.has_value(); }, 10000));
        QVERIFY(!*early);
        // The first reply brings both the position and the resolution: the
        // set is refused for the first (session/rotatorsession_moves.cpp,
        // requirePositionRead), and the codec's set would refuse it for the second.
        QVERIFY2(early->refusal == QStringLiteral("no position read from the controller yet"), qPrintable(early->refusal));
        QVERIFY(runEventLoopUntil([&] { return s.hasPosition(); }, 10000));
        QVERIFY(s.gotoPosition(50, 10));
    }

    // At 600 baud a status and its reply take 0.42 s: the session polls
    // every 0.84 s, not ten times a second, and waits long enough for the
    // answer.
    void pollsAtTheLinesPace()
    {
        RotatorSession s;
        QVERIFY(open(s, Dialect::Rot2Prog, QStringLiteral("baud=600&start_az=10&start_el=10")));
        const int exchangeMs = int(std::ceil((spid::kCommandSize + spid::kReplySize) * 10 * 1000.0 / 600));
        QCOMPARE(exchangeMs, 417);
        QCOMPARE(s.pollIntervalMs(), 2 * exchangeMs);
        QVERIFY(s.replyTimeoutMs() >= exchangeMs + 300);
        QSignalSpy failed(&s, &RotatorSession::requestFailed);
        QVERIFY(s.gotoPosition(40, 30));
        QVERIFY(arrives(s, 40, 30));
        QCOMPARE(failed.size(), 0);
        // A fast line is polled at the profile's rate.
        RotatorSession fast;
        QVERIFY(open(fast, Dialect::Md01, QStringLiteral("baud=115200")));
        QCOMPARE(fast.pollIntervalMs(), 1000 / fast.profile().pollHz);
    }

    // slew-sim as its own process on a pty, opened as a serial port at 600
    // baud: the serial link class, the line's real pacing, and the frames.
    void againstSlewSimOnAPty()
    {
        QTemporaryDir dir;
        const QString pty = dir.filePath(QStringLiteral("rot2prog"));
        SlewSimProcess sim;
        QVERIFY2(sim.start({"--model", "satnogs", "--time-scale", "4", "--pty", pty, "--dialect", "rot2prog", "--baud", "600",
                            "--start-az", "20", "--start-el", "10"}),
                 qPrintable(sim.error()));
        RotatorSession s;
        slew::model::RotatorProfile profile;
        profile.dialect = Dialect::Rot2Prog;
        s.setProfile(profile);
        QSignalSpy failed(&s, &RotatorSession::requestFailed);
        s.connectTo(QStringLiteral("serial:%1?baud=600").arg(pty));
        QVERIFY(runEventLoopUntil([&] { return s.capabilities().probed && s.hasPosition(); }, 15000));
        QCOMPARE(s.pollIntervalMs(), 834);
        QVERIFY(s.gotoPosition(75, 40));
        QVERIFY(runEventLoopUntil([&] { return std::abs(s.azimuth() - 75) < 0.3 && std::abs(s.elevation() - 40) < 0.3; },
                                  30000));
        QVERIFY(s.stop(QStringLiteral("the test")));
        QVERIFY(runEventLoopUntil([&] { return !s.positionStale(); }, 5000));
        QCOMPARE(failed.size(), 0);
        s.disconnectFromRotator();
        QCOMPARE(sim.stop(), 0);
        QVERIFY2(sim.standardError().contains(" 0 rejected"), sim.standardError().constData());
    }
};

QTEST_MAIN(SpidSessionTest)
#include "tst_spidsession.moc"
