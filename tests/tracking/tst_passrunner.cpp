// SPDX-License-Identifier: GPL-3.0-or-later
// The station service's pass runner: the reverse hold (a pass waits while
// another tracker steers the rotator, and starts once it is quiet), and a
// stop while a pass is still being planned on the worker thread, and a pass
// past the elements' age limit left alone.

#include "../common/simulatorpump.h"
#include "linkschemes.h"
#include "session/rotatorsession.h"
#include "sky/elementset.h"
#include "sky/tleformat.h"
#include "sky/utctime.h"
#include "tracking/passrunner.h"

#include <QFile>
#include <QSignalSpy>
#include <QTest>
#include <QThreadPool>

using slew::session::RotatorSession;
using namespace slew::tracking;

namespace {

const slew::sky::Site kStation{55.7, 12.6, 10, {}, {}};

bool logged(const QSignalSpy &lines, const QString &part)
{
    for (const QList<QVariant> &line : lines) {
        if (line.at(0).toString().contains(part))
            return true;
    }
    return false;
}

} // namespace

class PassRunnerTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { slew::registerLinkSchemes(); }

    void waitsWhileAnotherTrackerSteers()
    {
        RotatorSession session;
        session.connectTo(QStringLiteral("sim:"));
        QVERIFY(runEventLoopUntil([&] { return session.capabilities().probed && session.hasPosition(); }, 10000));
        QSignalSpy gotos(&session, &RotatorSession::targetChanged);

        PassRunner runner(&session);
        QString steering = QStringLiteral("127.0.0.1:40000");
        int asked = 0;
        runner.setOtherSteering([&] {
            ++asked;
            return steering;
        });
        QSignalSpy lines(&runner, &PassRunner::logLine);
        const StationClock clock;
        const auto target = TrackTarget::parseFixedOrCelestial(QStringLiteral("azel:200,30"), nullptr);
        QVERIFY(target);
        runner.start(*target, kStation, 0.0, &clock);

        QVERIFY(logged(lines, QStringLiteral("127.0.0.1:40000 is steering the rotator; tracking waits")));
        // It looks again (every second), says so once, and sends nothing.
        QVERIFY(runEventLoopUntil([&] { return asked >= 3; }, 10000));
        int said = 0;
        for (const QList<QVariant> &line : lines)
            said += line.at(0).toString().contains(QStringLiteral("is steering")) ? 1 : 0;
        QCOMPARE(said, 1);
        QVERIFY(!runner.isActive());
        QCOMPARE(gotos.count(), 0);

        // Quiet now: the direction is held.
        steering.clear();
        QVERIFY(runEventLoopUntil([&] { return runner.isActive(); }, 10000));
        QVERIFY(logged(lines, QStringLiteral("has been quiet for 10 s: Slew takes the rotator")));
        QVERIFY(logged(lines, QStringLiteral("holding azimuth 200.00°, elevation 30.00°")));
        QVERIFY(runEventLoopUntil([&] { return gotos.count() > 0; }, 10000));
        runner.stop(QStringLiteral("done"));
    }

    // Stop while the next pass is still being planned: the plan, when it
    // comes, starts nothing.
    void aStopWhilePlanningStartsNothing()
    {
        RotatorSession session;
        session.connectTo(QStringLiteral("sim:"));
        QVERIFY(runEventLoopUntil([&] { return session.capabilities().probed && session.hasPosition(); }, 10000));
        PassRunner runner(&session);
        const StationClock clock;
        TrackTarget moon;
        moon.kind = TrackTarget::Kind::Moon;
        runner.start(moon, kStation, 0.0, &clock);
        runner.stop(QStringLiteral("stopped at once"));
        QVERIFY(QTest::qWaitFor([] { return QThreadPool::globalInstance()->activeThreadCount() == 0; }, 10000));
        QCoreApplication::processEvents();
        QVERIFY(!runner.isRunning());
        QVERIFY(!runner.isActive());
        QCOMPARE(runner.tracker().state(), Tracker::State::Idle);
    }

    // The window's Time controller moves the station clock while a target
    // is held: the runner lets go of the old plan and plans again by the
    // clock's new time, as it would for a new target, and keeps tracking.
    void aClockChangePlansAgain()
    {
        RotatorSession session;
        session.connectTo(QStringLiteral("sim:"));
        QVERIFY(runEventLoopUntil([&] { return session.capabilities().probed && session.hasPosition(); }, 10000));
        PassRunner runner(&session);
        QSignalSpy lines(&runner, &PassRunner::logLine);
        StationClock clock(slew::sky::julianFromIso(QStringLiteral("2018-01-22T07:00:00Z")), 1.0);
        const auto target = TrackTarget::parseFixedOrCelestial(QStringLiteral("azel:200,30"), nullptr);
        QVERIFY(target);
        runner.start(*target, kStation, 0.0, &clock);
        QVERIFY(runEventLoopUntil([&] { return runner.isActive() && !runner.tracker().plan().path.isEmpty(); }, 10000));
        QVERIFY(logged(lines, QStringLiteral("holding azimuth 200.00°, elevation 30.00° until 2018-01-2")));

        clock.rehearse(*slew::sky::julianFromIso(QStringLiteral("2026-11-25T12:00:00Z")), 5.0);
        QVERIFY(logged(lines, QStringLiteral("planning again: the station clock was changed")));
        QVERIFY(logged(lines, QStringLiteral("rehearsal clock from 2026-11-25T12:00:0")));
        QVERIFY(runner.isRunning());
        QVERIFY(runEventLoopUntil([&] { return logged(lines, QStringLiteral("until 2026-11-2")); }, 10000));
        QVERIFY(runEventLoopUntil([&] { return runner.isActive(); }, 10000));
        // Letting go of the old plan is not the end of tracking.
        QVERIFY(!logged(lines, QStringLiteral("tracking ended")));

        // Back to real time: the same again, and a stop ends it for good.
        clock.followRealTime();
        QVERIFY(runner.isRunning());
        runner.stop(QStringLiteral("done"));
        clock.rehearse(*slew::sky::julianFromIso(QStringLiteral("2018-01-22T07:00:00Z")), 1.0);
        QVERIFY(!runner.isRunning());
    }

    // Elements within the limit now, past it by the next pass's AOS: that
    // pass is not tracked, the runner says why and stops (later passes are
    // further still), and the rotator is never sent anywhere.
    void aPassPastTheElementsAgeIsNotTracked()
    {
        QFile file(QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle"));
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QList<slew::sky::ElementSet> sets = slew::sky::readTleText(QString::fromLatin1(file.readAll())).sets;
        const QList<const slew::sky::ElementSet *> found = slew::sky::findSatellites(sets, QStringLiteral("FLOCK 2P-1"));
        QCOMPARE(found.size(), 1);
        TrackTarget flock;
        flock.elements = *found.first();

        RotatorSession session;
        session.connectTo(QStringLiteral("sim:"));
        QVERIFY(runEventLoopUntil([&] { return session.capabilities().probed && session.hasPosition(); }, 10000));
        QSignalSpy gotos(&session, &RotatorSession::targetChanged);
        PassRunner runner(&session);
        QSignalSpy lines(&runner, &PassRunner::logLine);
        // 07:00, the pass rises after 07:30: a limit five minutes past the
        // age now.
        const StationClock clock(slew::sky::julianFromIso(QStringLiteral("2018-01-22T07:00:00Z")).value(), 1.0);
        const double ageNow = clock.nowJulian() - flock.elements.epochJulian();
        runner.setElementAgeLimitDays(ageNow + 5.0 / 1440.0);
        runner.start(flock, kStation, 0.0, &clock);
        QVERIFY(runEventLoopUntil([&] { return !runner.isRunning(); }, 20000));
        QVERIFY2(logged(lines, QStringLiteral("the pass of FLOCK 2P-1 at 2018-01-22T07:")), qPrintable(lines.last().at(0).toString()));
        QVERIFY(logged(lines, QStringLiteral("is not tracked: its elements are 1.4 days from AOS (epoch 2018-01-20T22:08:")));
        QVERIFY(logged(lines, QStringLiteral("refresh the element sets or raise the limit")));
        QVERIFY(!runner.isActive());
        QCOMPARE(gotos.count(), 0);

        // The same pass with a day's more leeway is planned and taken.
        runner.setElementAgeLimitDays(ageNow + 1.0);
        runner.start(flock, kStation, 0.0, &clock);
        QVERIFY(runEventLoopUntil([&] { return runner.isActive(); }, 20000));
        QVERIFY(logged(lines, QStringLiteral("next pass: FLOCK 2P-1, AOS 2018-01-22T07:")));
        runner.stop(QStringLiteral("done"));
        const qsizetype sent = gotos.count();

        // Before the epoch (a rehearsal of an earlier day with these
        // elements) later passes come nearer to it: the runner skips the
        // pass and waits for the next instead of giving up.
        const StationClock before(flock.elements.epochJulian() - 1.5, 1.0);
        runner.setElementAgeLimitDays(1.2);
        lines.clear();
        runner.start(flock, kStation, 0.0, &before);
        QVERIFY(runEventLoopUntil([&] { return logged(lines, QStringLiteral("trying the next one after its LOS")); }, 20000));
        QVERIFY(logged(lines, QStringLiteral("is not tracked: its elements are 1.")));
        QVERIFY(runner.isRunning());
        QVERIFY(!runner.isActive());
        runner.stop(QStringLiteral("done"));
        QCOMPARE(gotos.count(), sent); // nothing sent for the skipped pass
    }
};

QTEST_MAIN(PassRunnerTest)
#include "tst_passrunner.moc"
