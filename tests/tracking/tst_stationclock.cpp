// SPDX-License-Identifier: GPL-3.0-or-later
// The station clock as the window's Time controller changes it: a rehearsal
// from a chosen instant at 1 to 20 times real time, a new rate that goes on
// from the time the clock reads, and back to real time, each said with
// changed(); a pause that holds the instant and a step forward while
// paused, each said with its own signal so nobody plans again. Rates are measured against wall readings taken around each
// clock reading, so the check holds however busy the machine is.

#include "sky/skyvector.h"
#include "sky/utctime.h"
#include "tracking/stationclock.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>

#include <cmath>
#include <limits>

using slew::tracking::StationClock;

namespace {

constexpr double kJulianSlackSeconds = 0.001; // a Julian date in a double resolves ~40 µs

// A wall clock runs on wall time: let some pass on the event loop.
bool letWallTimePass(int ms)
{
    QTimer timer;
    timer.setSingleShot(true);
    QSignalSpy done(&timer, &QTimer::timeout);
    timer.start(ms);
    return done.wait(ms + 10000);
}

// Station seconds that pass over a stretch of wall time, and that stretch
// bracketed: at least `inner`, at most `outer` wall seconds.
struct Stretch {
    double station = 0, inner = 0, outer = 0;
    QString describe(double rate) const
    {
        return QStringLiteral("%1 station s in %2..%3 wall s at ×%4").arg(station).arg(inner).arg(outer).arg(rate);
    }
    bool runsAt(double rate) const
    {
        return station >= rate * inner - kJulianSlackSeconds && station <= rate * outer + kJulianSlackSeconds;
    }
};

Stretch measure(const StationClock &clock, int ms)
{
    QElapsedTimer wall;
    wall.start();
    const auto wallNow = [&] { return double(wall.nsecsElapsed()) / 1e9; };
    Stretch s;
    const double w0 = wallNow();
    const double first = clock.nowJulian();
    const double w1 = wallNow();
    if (!letWallTimePass(ms))
        return s;
    const double w2 = wallNow();
    const double second = clock.nowJulian();
    const double w3 = wallNow();
    s.station = (second - first) * slew::sky::kSecondsPerDay;
    s.inner = w2 - w1;
    s.outer = w3 - w0;
    return s;
}

const double kStart = *slew::sky::julianFromIso(QStringLiteral("2026-11-25T12:00:00Z"));

} // namespace

class StationClockTest : public QObject {
    Q_OBJECT
private slots:
    void aRehearsalStartsWhereAskedAndRunsAtItsRate()
    {
        StationClock clock;
        QVERIFY(!clock.isRehearsal());
        QSignalSpy changed(&clock, &StationClock::changed);
        clock.rehearse(kStart, 5.0);
        QCOMPARE(changed.count(), 1);
        QVERIFY(clock.isRehearsal());
        QCOMPARE(clock.rate(), 5.0);
        QVERIFY((clock.nowJulian() - kStart) * slew::sky::kSecondsPerDay < 5.0); // five times a moment at most
        const Stretch s = measure(clock, 200);
        QVERIFY2(s.runsAt(5.0), qPrintable(s.describe(5.0)));
        QVERIFY2(!s.runsAt(1.0), qPrintable(s.describe(1.0)));
    }

    void aNewRateGoesOnFromWhereTheClockIs()
    {
        StationClock clock;
        clock.rehearse(kStart, 1.0);
        QVERIFY(letWallTimePass(50));
        QElapsedTimer wall;
        wall.start();
        const double before = clock.nowJulian();
        clock.setRate(10.0);
        const double after = clock.nowJulian();
        const double took = double(wall.nsecsElapsed()) / 1e9;
        // No jump: on from where it was, by at most ten times the moment between.
        const double moved = (after - before) * slew::sky::kSecondsPerDay;
        QVERIFY2(moved >= -kJulianSlackSeconds && moved <= 10.0 * took + kJulianSlackSeconds,
                 qPrintable(QStringLiteral("moved %1 s in %2 s").arg(moved).arg(took)));
        QCOMPARE(clock.rate(), 10.0);
        const Stretch s = measure(clock, 200);
        QVERIFY2(s.runsAt(10.0), qPrintable(s.describe(10.0)));
        // Rates beyond what a simulator can keep up with are held to it.
        clock.setRate(100.0);
        QCOMPARE(clock.rate(), StationClock::kMaxRate);
    }

    void realTimeIsTheSystemsUtcAgain()
    {
        StationClock clock(kStart, 20.0);
        QVERIFY(clock.isRehearsal());
        QSignalSpy changed(&clock, &StationClock::changed);
        clock.followRealTime();
        QCOMPARE(changed.count(), 1);
        QVERIFY(!clock.isRehearsal());
        QCOMPARE(clock.rate(), 1.0);
        QVERIFY(std::abs(clock.nowJulian() - slew::sky::julianNow()) * slew::sky::kSecondsPerDay < 1.0);
        // Real time has no rate of its own to change, and says nothing.
        clock.setRate(5.0);
        clock.followRealTime();
        QCOMPARE(changed.count(), 1);
        QCOMPARE(clock.rate(), 1.0);
    }

    void aPauseHoldsTheInstantAndResumeRunsOnFromIt()
    {
        StationClock clock;
        clock.rehearse(kStart, 5.0);
        QSignalSpy changed(&clock, &StationClock::changed);
        QSignalSpy paused(&clock, &StationClock::pausedChanged);
        clock.pause();
        QVERIFY(clock.isPaused());
        QCOMPARE(paused.count(), 1);
        QCOMPARE(paused.last().at(0).toBool(), true);
        const double held = clock.nowJulian();
        QVERIFY(letWallTimePass(100));
        QCOMPARE(clock.nowJulian(), held);
        // A new rate while paused: kept for the resume, the instant held.
        clock.setRate(10.0);
        QCOMPARE(clock.rate(), 10.0);
        QVERIFY(clock.isPaused());
        QCOMPARE(clock.nowJulian(), held);

        clock.resume();
        QVERIFY(!clock.isPaused());
        QCOMPARE(paused.count(), 2);
        QCOMPARE(paused.last().at(0).toBool(), false);
        // On from the instant it held, at the rate chosen.
        QVERIFY(clock.nowJulian() >= held);
        QVERIFY((clock.nowJulian() - held) * slew::sky::kSecondsPerDay < 5.0);
        const Stretch s = measure(clock, 200);
        QVERIFY2(s.runsAt(10.0), qPrintable(s.describe(10.0)));
        // Only the new rate made planners plan again: a pause does not.
        QCOMPARE(changed.count(), 1);
    }

    void aStepMovesAPausedClockForwardOnly()
    {
        StationClock clock(kStart, 2.0);
        QSignalSpy stepped(&clock, &StationClock::stepped);
        QSignalSpy changed(&clock, &StationClock::changed);
        // Running: a step is refused and changes nothing.
        QVERIFY(!clock.step(30.0));
        clock.pause();
        const double held = clock.nowJulian();
        QVERIFY(clock.step(30.0));
        QCOMPARE(stepped.count(), 1);
        QVERIFY(std::abs((clock.nowJulian() - held) * slew::sky::kSecondsPerDay - 30.0) < kJulianSlackSeconds);
        QVERIFY(clock.isPaused());
        // Nothing backwards, nothing that is not a number.
        for (const double bad : {0.0, -10.0, std::nan(""), std::numeric_limits<double>::infinity()})
            QVERIFY(!clock.step(bad));
        QCOMPARE(stepped.count(), 1);
        QVERIFY(std::abs((clock.nowJulian() - held) * slew::sky::kSecondsPerDay - 30.0) < kJulianSlackSeconds);
        QCOMPARE(changed.count(), 0);
    }

    void aPausedClockIsMovedAsOneChange()
    {
        // The window's slider moves a paused rehearsal: it lands on the
        // instant asked, however long the planners take to answer, and
        // stays paused without saying otherwise on the way.
        StationClock clock(kStart, 2.0);
        QVERIFY(!clock.holdAt(kStart + 1.0)); // running: rehearse() moves it
        clock.pause();
        QSignalSpy changed(&clock, &StationClock::changed);
        QSignalSpy paused(&clock, &StationClock::pausedChanged);
        const double to = kStart + 30.0 / (24.0 * 60.0);
        QVERIFY(clock.holdAt(to));
        QVERIFY(letWallTimePass(50));
        QCOMPARE(clock.nowJulian(), to);
        QVERIFY(clock.isPaused());
        QCOMPARE(changed.count(), 1);
        QCOMPARE(paused.count(), 0);
        QVERIFY(!clock.holdAt(std::nan("")));
        QCOMPARE(clock.nowJulian(), to);
        clock.resume();
        QVERIFY(clock.nowJulian() >= to);
    }

    void pausingRealTimeMakesARehearsalHeldAtNow()
    {
        StationClock clock;
        clock.pause();
        QVERIFY(clock.isRehearsal());
        QVERIFY(clock.isPaused());
        QCOMPARE(clock.rate(), 1.0);
        const double held = clock.nowJulian();
        QVERIFY(std::abs(held - slew::sky::julianNow()) * slew::sky::kSecondsPerDay < 1.0);
        QVERIFY(letWallTimePass(50));
        QCOMPARE(clock.nowJulian(), held);
        // Back to real time, or a new start: running again, and said so.
        QSignalSpy paused(&clock, &StationClock::pausedChanged);
        clock.followRealTime();
        QVERIFY(!clock.isPaused());
        QVERIFY(!clock.isRehearsal());
        QCOMPARE(paused.count(), 1);
        clock.pause();
        clock.rehearse(kStart, 1.0);
        QVERIFY(!clock.isPaused());
        QCOMPARE(paused.count(), 3);
        QVERIFY(clock.nowJulian() >= kStart);
    }
};

QTEST_MAIN(StationClockTest)
#include "tst_stationclock.moc"
