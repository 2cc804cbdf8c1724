// SPDX-License-Identifier: GPL-3.0-or-later
// PollPace, the session's choice of poll interval (session/pollpace.h), by
// itself; and the rest rate as the profile sets it, through a session on a
// manual-clock simulator.

#include "../common/simulatorpump.h"
#include "linkschemes.h"
#include "protocol/encoder.h"
#include "session/pollpace.h"
#include "session/rotatorsession.h"
#include "sim/simulator.h"
#include "sim/simulatorscheme.h"

#include <QSignalSpy>
#include <QTest>

using namespace slew;
using session::PollPace;
using session::RotatorSession;

class PollPaceTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { registerLinkSchemes(); }

    void fullUntilQuietThenRest()
    {
        PollPace pace;
        pace.setIntervals(100, 1000);
        pace.restart(0);
        pace.notePosition(10.0, 20.0, 0);
        QCOMPARE(pace.intervalMs(PollPace::kQuietMs - 1), 100);
        QVERIFY(pace.resting(PollPace::kQuietMs));
        QCOMPARE(pace.intervalMs(PollPace::kQuietMs), 1000);
        // Jitter is not motion; a move is, and so is anything that wakes it.
        pace.notePosition(10.0 + PollPace::kMovedDegrees / 2, 20.0, PollPace::kQuietMs + 100);
        QVERIFY(pace.resting(PollPace::kQuietMs + 100));
        pace.notePosition(10.0, 20.0 + 2 * PollPace::kMovedDegrees, PollPace::kQuietMs + 200);
        QCOMPARE(pace.intervalMs(PollPace::kQuietMs + 200), 100);
        pace.wake(3 * PollPace::kQuietMs);
        QCOMPARE(pace.intervalMs(4 * PollPace::kQuietMs - 1), 100);
        // A rest rate faster than the full one is the full one.
        pace.setIntervals(500, 200);
        QCOMPARE(pace.restMs(), 500);
    }

    void slowDriftAddsUpToMotion()
    {
        // A rotator creeping a hundredth of a degree between polls never
        // moves from one poll to the next by more than the jitter allowance,
        // but it does move: measured from where it last stood still, the
        // drift adds up.
        PollPace pace;
        pace.setIntervals(100, 1000);
        pace.restart(0);
        qint64 now = 0;
        double az = 10.0;
        for (; now < PollPace::kQuietMs + 1000; now += 100)
            pace.notePosition(az, 20.0, now);
        QVERIFY(pace.resting(now));
        int polls = 0;
        while (pace.resting(now) && polls < 20) {
            az += 0.01;
            pace.notePosition(az, 20.0, now);
            now += pace.intervalMs(now);
            ++polls;
        }
        QVERIFY2(!pace.resting(now) && polls <= 6, qPrintable(QString::number(polls)));
        QCOMPARE(pace.intervalMs(now), 100);
    }

    void theRestRateIsTheProfiles()
    {
        model::RotatorProfile profile;
        profile.restPollHz = 0.5;
        RotatorSession s;
        s.setProfile(profile);
        s.connectTo(QStringLiteral("sim:?clock=manual"));
        (new SimulatorPump(0.005, &s))->follow(&s);
        QVERIFY(runEventLoopUntil([&] { return s.capabilities().probed && s.hasPosition(); }, 10000));
        QCOMPARE(s.pollIntervalMs(), 100);
        QCOMPARE(s.restPollIntervalMs(), 2000);
        QVERIFY(!s.pollingAtRest());
        QVERIFY(runFor(s, PollPace::kQuietMs / 1000.0 + 3.0));
        QVERIFY(s.pollingAtRest());
        const int resting = pollsIn(s, 20.0);
        QVERIFY2(resting >= 9 && resting <= 11, qPrintable(QString::number(resting)));
        // A tracker asking (the rotctld server calls this) wakes it.
        s.wakePolling();
        QVERIFY(!s.pollingAtRest());
        const int woken = pollsIn(s, 1.0);
        QVERIFY2(woken >= 9, qPrintable(QString::number(woken)));
        // A rest rate at the full rate is polling as ever, and a profile
        // changed at rest takes effect at once.
        QVERIFY(runFor(s, PollPace::kQuietMs / 1000.0 + 1.0));
        profile.pollHz = 2;
        profile.restPollHz = 2;
        s.setProfile(profile);
        QCOMPARE(s.restPollIntervalMs(), 500);
        const int same = pollsIn(s, 10.0);
        QVERIFY2(same >= 19 && same <= 21, qPrintable(QString::number(same)));
    }

private:
    static bool runFor(RotatorSession &s, double seconds)
    {
        sim::Simulator *sim = sim::simulatorBehind(s.link());
        const double until = sim->clock().now() + seconds;
        return runEventLoopUntil([&] { return sim->clock().now() >= until; }, 60000);
    }
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
};

QTEST_MAIN(PollPaceTest)
#include "tst_pollpace.moc"
