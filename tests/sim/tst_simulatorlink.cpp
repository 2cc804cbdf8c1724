// SPDX-License-Identifier: GPL-3.0-or-later
// The `sim:` link: made from a URI, opened and used like any other link,
// with its clock stepped by the test.
#include "sim/simulator.h"
#include "sim/simulatorconnection.h"
#include "sim/simulatorlink.h"
#include "session/connectionplan.h"
#include "sim/simulatorscheme.h"

#include "transport/linkfactory.h"

#include <QElapsedTimer>
#include <QIODevice>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>

using namespace slew::sim;
using slew::transport::createLink;
using slew::transport::Link;

class TestSimulatorLink : public QObject {
    Q_OBJECT

    std::unique_ptr<Link> openLink(const QString &uri)
    {
        auto result = createLink(uri);
        if (!result.link)
            qWarning() << result.error;
        Link *link = result.link.get();
        if (!link)
            return {};
        QSignalSpy opened(link, &Link::opened);
        link->open();
        if (!link->isOpen() && !opened.wait(2000))
            return {};
        return std::move(result.link);
    }

    // Writes a command and returns the reply line that follows.
    static QByteArray ask(Link *link, const QByteArray &line)
    {
        QIODevice *d = link->device();
        d->write(line);
        QByteArray reply;
        QSignalSpy ready(d, &QIODevice::readyRead);
        while (!reply.endsWith('\n')) {
            if (d->bytesAvailable() == 0 && !ready.wait(2000))
                break;
            reply += d->readAll();
        }
        return reply;
    }

    // A wall clock runs on wall time: let some pass on the event loop.
    static bool letWallTimePass(int ms)
    {
        QTimer timer;
        timer.setSingleShot(true);
        QSignalSpy done(&timer, &QTimer::timeout);
        timer.start(ms);
        return done.wait(ms + 10000);
    }

    // Lets queued deliveries run: what is due has arrived afterwards.
    static void settle()
    {
        for (int i = 0; i < 10; ++i)
            QCoreApplication::processEvents();
    }

    // Sends `GE` and checks that its answer is held while the simulated clock
    // stands before `due` seconds and released once the clock passes it.
    static void expectGeHeldUntil(Link *link, double due)
    {
        Simulator *sim = simulatorBehind(link);
        QIODevice *d = link->device();
        QSignalSpy ready(d, &QIODevice::readyRead);
        d->write("GE\n");
        settle();
        sim->advance(due * 0.9);
        settle();
        QCOMPARE(d->bytesAvailable(), 0);
        sim->advance(due * 0.2);
        QVERIFY(ready.wait(2000));
        QCOMPARE(d->readAll(), QByteArray("GE1\n"));
    }

private slots:
    void initTestCase() { registerSimulatorScheme(); }

    void queryItemsSetThePlant()
    {
        auto link = openLink("sim:?clock=manual&kp=30&ki=0&kd=5&az_max=450&el_max=90&ticks_per_deg=1000"
                             "&dialect=satnogs&park_az=90");
        QVERIFY(link);
        Simulator *sim = simulatorBehind(link.get());
        QVERIFY(sim);
        QVERIFY(sim->clock().isManual());
        const SimulatedRotator &r = sim->rotator();
        QCOMPARE(r.axis(Axis::Azimuth).gains().kp, 30.0);
        QCOMPARE(r.axis(Axis::Elevation).gains().kd, 5.0);
        QCOMPARE(r.axis(Axis::Azimuth).plant().maxDegrees, 450.0);
        QCOMPARE(r.axis(Axis::Elevation).plant().maxDegrees, 90.0);
        QCOMPARE(r.axis(Axis::Azimuth).plant().ticksPerDegree, 1000.0);
        QCOMPARE(sim->options().dialect, slew::protocol::Dialect::SatNogs);
        QCOMPARE(ask(link.get(), "CR 7\n"), QByteArray("7,90.00\n"));
    }

    void modelAndDriveItemsNameTheRotator()
    {
        auto plain = openLink("sim:?clock=manual");
        const SimulatedRotator &byDefault = simulatorBehind(plain.get())->rotator();
        QCOMPARE(byDefault.axis(Axis::Azimuth).plant().maxSpeed, 6.2);
        QCOMPARE(byDefault.axis(Axis::Elevation).plant().maxSpeed, 2.7);
        QCOMPARE(byDefault.axis(Axis::Azimuth).plant().driveTrain, DriveTrain::SelfLocking);

        auto fast = openLink("sim:?clock=manual&model=satnogs&drive=free");
        const SimulatedRotator &f = simulatorBehind(fast.get())->rotator();
        QCOMPARE(f.axis(Axis::Azimuth).plant().maxSpeed, 30.0);
        QCOMPARE(f.axis(Axis::Elevation).plant().maxSpeed, 30.0);
        QCOMPARE(f.axis(Axis::Elevation).plant().driveTrain, DriveTrain::FreeRunning);

        // The model is the starting point wherever it stands; other items adjust it.
        auto heavy = openLink("sim:?clock=manual&max_speed=1.5&model=heavy");
        const SimulatedRotator &h = simulatorBehind(heavy.get())->rotator();
        QCOMPARE(h.axis(Axis::Azimuth).plant().maxSpeed, 1.5);
        QCOMPARE(h.axis(Axis::Azimuth).plant().maxAcceleration, 2.0);
    }

    void aProfileFollowsTheSimulatorUri()
    {
        const auto profileForSimulator = [](const slew::model::RotatorProfile &profile, const QString &uri) {
            return slew::session::profileWithHints(profile, slew::transport::linkHintsFor(uri));
        };
        slew::model::RotatorProfile mine;
        mine.name = QStringLiteral("mine");
        const auto p = profileForSimulator(mine, QStringLiteral("sim:?az_max=450&el_max=180&park_az=90&park_el=10&dialect=satnogs"));
        QCOMPARE(p.name, QStringLiteral("mine"));
        QCOMPARE(p.limits.azMax, 450.0);
        QCOMPARE(p.limits.elMax, 180.0);
        QCOMPARE(p.parkAz, 90.0);
        QCOMPARE(p.parkEl, 10.0);
        QCOMPARE(p.dialect, slew::protocol::Dialect::SatNogs);
        QVERIFY(p.validate().isEmpty());
        // Other links, and a sim: URI with a bad item, leave the profile alone.
        QCOMPARE(profileForSimulator(mine, QStringLiteral("tcp://h:1")).limits.azMax, 360.0);
        QCOMPARE(profileForSimulator(mine, QStringLiteral("sim:?az_max=999")).limits.azMax, 360.0);
        // What the URI does not name keeps the profile's (tighter) value.
        QCOMPARE(profileForSimulator(mine, QStringLiteral("sim:")).limits.elMax, 90.0);
        QCOMPARE(profileForSimulator(mine, QStringLiteral("sim:")).dialect, slew::protocol::Dialect::Easycomm3);
    }

    void theLinkKeepsTheSimulatorsClock()
    {
        auto link = openLink("sim:?clock=manual");
        QVERIFY(link->clockSeconds());
        const double before = *link->clockSeconds();
        simulatorBehind(link.get())->clock().advance(2.5);
        QCOMPARE(*link->clockSeconds(), before + 2.5);
        // Hardware has no clock of its own to offer.
        const auto tcp = slew::transport::createLink(QStringLiteral("tcp://127.0.0.1:1"));
        QVERIFY(tcp.link);
        QVERIFY(!tcp.link->clockSeconds());
        QVERIFY(tcp.link->hints().dialect.isEmpty());
    }

    // A scaled wall clock: simulated time is the wall time between two
    // readings taken around it, times the scale, so the check cannot race.
    void aTimeScaleRunsTheWallClockFaster()
    {
        auto link = openLink("sim:?time_scale=8");
        QVERIFY(link);
        const SimClock &clock = simulatorBehind(link.get())->clock();
        QVERIFY(!clock.isManual());
        QCOMPARE(clock.timeScale(), 8.0);
        // Wall readings bracket each clock reading: w0 <= start <= w1 and
        // w2 <= end <= w3, so 8 (w2 - w1) <= simulated <= 8 (w3 - w0).
        QElapsedTimer wall;
        wall.start();
        const auto wallNow = [&] { return double(wall.nsecsElapsed()) / 1e9; };
        const double w0 = wallNow();
        const double simStart = clock.now();
        const double w1 = wallNow();
        // Wall time has to pass for a wall clock: wait on it, not a nap.
        QVERIFY(QTest::qWaitFor([&] { return wallNow() >= w1 + 0.05; }, 5000));
        const double w2 = wallNow();
        const double simulated = clock.now() - simStart;
        const double w3 = wallNow();
        QVERIFY2(simulated >= 8.0 * (w2 - w1) && simulated <= 8.0 * (w3 - w0),
                 qPrintable(QStringLiteral("%1 s simulated in %2..%3 s").arg(simulated).arg(w2 - w1).arg(w3 - w0)));
        // A manual clock ignores the scale: it moves only when stepped.
        SimClock manual(SimClock::Mode::Manual, 8.0);
        manual.advance(1.5);
        QCOMPARE(manual.now(), 1.5);
    }

    // The window's Time controller sets the pace of a running simulator: it
    // goes on from the time it reads, so the rotator carries on from where
    // it is, and runs at the new scale from there. Links with no clock of
    // their own to scale say so.
    void aRunningSimulatorTakesANewTimeScaleFromWhereItIs()
    {
        auto link = openLink("sim:");
        QVERIFY(link);
        const SimClock &clock = simulatorBehind(link.get())->clock();
        QCOMPARE(clock.timeScale(), 1.0);
        QElapsedTimer wall;
        wall.start();
        const auto wallNow = [&] { return double(wall.nsecsElapsed()) / 1e9; };
        QVERIFY(letWallTimePass(50));
        const double w0 = wallNow();
        const double before = clock.now();
        QVERIFY(link->setTimeScale(5.0));
        const double atFive = clock.now();
        const double w1 = wallNow();
        QCOMPARE(clock.timeScale(), 5.0);
        // No jump: on from where it was, by at most five times the moment between.
        QVERIFY2(atFive >= before && atFive - before <= 5.0 * (w1 - w0),
                 qPrintable(QStringLiteral("%1 s then %2 s").arg(before).arg(atFive)));
        QVERIFY(letWallTimePass(50));
        const double w2 = wallNow();
        const double simulated = clock.now() - atFive;
        const double w3 = wallNow();
        QVERIFY2(simulated >= 5.0 * (w2 - w1) && simulated <= 5.0 * (w3 - w0),
                 qPrintable(QStringLiteral("%1 s simulated in %2..%3 s").arg(simulated).arg(w2 - w1).arg(w3 - w0)));
        // Back to real time, held to the simulator's range on the way.
        QVERIFY(link->setTimeScale(1.0));
        QCOMPARE(clock.timeScale(), 1.0);
        QVERIFY(link->setTimeScale(50.0));
        QCOMPARE(clock.timeScale(), SimClock::maxTimeScale);

        auto manual = openLink("sim:?clock=manual");
        QVERIFY(manual);
        QVERIFY(!manual->setTimeScale(5.0));
        QCOMPARE(simulatorBehind(manual.get())->clock().timeScale(), 1.0);
        const auto tcp = slew::transport::createLink(QStringLiteral("tcp://127.0.0.1:1"));
        QVERIFY(tcp.link);
        QVERIFY(!tcp.link->setTimeScale(5.0));
    }

    void badQueryItemsNameTheUri_data()
    {
        QTest::addColumn<QString>("uri");
        QTest::addColumn<QString>("item");
        QTest::newRow("az_max") << "sim:?az_max=500" << "az_max";
        QTest::newRow("el_max") << "sim:?el_max=100" << "el_max";
        QTest::newRow("kp") << "sim:?kp=fast" << "kp";
        QTest::newRow("dialect") << "sim:?dialect=gs232" << "dialect";
        QTest::newRow("unknown") << "sim:?warp=9" << "warp";
        QTest::newRow("jam") << "sim:?jam=roll" << "jam";
        QTest::newRow("model") << "sim:?model=g9999" << "model";
        QTest::newRow("drive") << "sim:?drive=belt" << "drive";
        QTest::newRow("time_scale too fast") << "sim:?time_scale=50" << "time_scale";
        QTest::newRow("time_scale backwards") << "sim:?time_scale=0.5" << "time_scale";
    }
    void badQueryItemsNameTheUri()
    {
        QFETCH(QString, uri);
        QFETCH(QString, item);
        const auto result = createLink(uri);
        QVERIFY(!result.link);
        QVERIFY2(result.error.contains(uri), qPrintable(result.error));
        QVERIFY2(result.error.contains(item), qPrintable(result.error));
    }

    void repliesArriveFromTheEventLoopNotInsideWrite()
    {
        auto link = openLink("sim:?clock=manual");
        QVERIFY(link);
        QIODevice *d = link->device();
        QSignalSpy ready(d, &QIODevice::readyRead);
        d->write("AZ EL\n");
        QCOMPARE(d->bytesAvailable(), 0);
        QCOMPARE(ready.count(), 0);
        QVERIFY(ready.wait(2000));
        QCOMPARE(d->readAll(), QByteArray("AZ0.00 EL0.00\n"));
    }

    void steppedClockMovesTheRotatorExactly()
    {
        auto link = openLink("sim:?clock=manual&model=satnogs&start_az=100");
        QVERIFY(link);
        Simulator *sim = simulatorBehind(link.get());
        // The GS answer proves the set before it was taken.
        QCOMPARE(ask(link.get(), "AZ110 EL10\nGS\n"), QByteArray("GS1542\n")); // both axes 6: servo, moving
        for (int i = 0; i < 160; ++i)
            sim->advance(0.025);
        QCOMPARE(sim->clock().now(), 4.0);
        QCOMPARE(sim->rotator().time(), 4.0);
        QCOMPARE(ask(link.get(), "GS\n"), QByteArray("GS1028\n"));
        const QList<QByteArray> position = ask(link.get(), "AZ EL\n").trimmed().split(' ');
        QCOMPARE(position.size(), 2);
        QVERIFY(qAbs(position[0].mid(2).toDouble() - 110.0) <= 0.1);
        QVERIFY(qAbs(position[1].mid(2).toDouble() - 10.0) <= 0.1);
    }

    void rejectedInputIsCountedAndAlarmed()
    {
        auto link = openLink("sim:?clock=manual");
        QVERIFY(link);
        Simulator *sim = simulatorBehind(link.get());
        QCOMPARE(ask(link.get(), "FOO\n"), QByteArray("ALunknown:FOO\n"));
        QCOMPARE(ask(link.get(), "EL200\n"), QByteArray("ALlimit:EL200.00\n"));
        QCOMPARE(sim->counters().unknown, 1u);
        QCOMPARE(sim->counters().outOfLimits, 1u);
        QCOMPARE(sim->counters().rejected(), 2u);
    }

    void latencyHoldsRepliesUntilTheClockPassesIt()
    {
        auto link = openLink("sim:?clock=manual&latency_ms=500");
        QVERIFY(link);
        expectGeHeldUntil(link.get(), 0.5);
    }

    void baudPacingTakesTheLineTime()
    {
        // 1200 baud: 120 characters a second; `GE\n` in, `GE1\n` out is 7.
        auto link = openLink("sim:?clock=manual&baud=1200");
        QVERIFY(link);
        expectGeHeldUntil(link.get(), 7.0 / 120.0);
    }

    void lossyLinkLosesEveryByteAtRateOne()
    {
        auto link = openLink("sim:?clock=manual&drop_rate=1");
        QVERIFY(link);
        Simulator *sim = simulatorBehind(link.get());
        link->device()->write("GE\nAZ\n");
        settle();
        sim->advance(1.0);
        settle();
        QCOMPARE(link->device()->bytesAvailable(), 0);
        QCOMPARE(sim->counters().commands, 2u); // heard, answered, lost on the way
        // Switched off at run time, the line works again.
        sim->setLinkFaults({});
        QCOMPARE(ask(link.get(), "GE\n"), QByteArray("GE1\n"));
    }

    void garbageBytesArriveAmongTheReplies()
    {
        auto link = openLink("sim:?clock=manual&garbage_rate=1&seed=3");
        QVERIFY(link);
        QIODevice *d = link->device();
        QSignalSpy ready(d, &QIODevice::readyRead);
        d->write("GE\n");
        QVERIFY(ready.wait(2000));
        const QByteArray got = d->readAll();
        QCOMPARE(got.size(), 8); // every one of the 4 bytes followed by one of garbage
        const QByteArray kept = QByteArray(1, got[0]) + got[2] + got[4] + got[6];
        QCOMPARE(kept, QByteArray("GE1\n"));
    }

    void droppedConnectionIsReportedAsLost()
    {
        auto link = openLink("sim:?clock=manual");
        QVERIFY(link);
        QSignalSpy lost(link.get(), &Link::lost);
        simulatorBehind(link.get())->dropConnections();
        QVERIFY(lost.wait(2000));
        QVERIFY(!link->isOpen());
        QVERIFY(lost.first().first().toString().contains("sim:"));

        auto timed = openLink("sim:?clock=manual&drop_after=2");
        QVERIFY(timed);
        QSignalSpy lostLater(timed.get(), &Link::lost);
        simulatorBehind(timed.get())->advance(1.9);
        QCoreApplication::processEvents();
        QVERIFY(timed->isOpen());
        simulatorBehind(timed.get())->advance(0.2);
        QVERIFY(lostLater.wait(2000));
    }

    void unsolicitedPushesFollowTheClock()
    {
        auto link = openLink("sim:?clock=manual&unsolicited=1");
        QVERIFY(link);
        Simulator *sim = simulatorBehind(link.get());
        QIODevice *d = link->device();
        QSignalSpy ready(d, &QIODevice::readyRead);
        sim->advance(0.025);
        QVERIFY(ready.wait(2000));
        const QByteArray first = d->readAll();
        QVERIFY2(first.startsWith("AZ0.00\nEL0.00\nIP0,25.00\n"), first.constData());
        d->write("VR10000\n");
        QTRY_VERIFY(sim->rotator().axis(Axis::Azimuth).mode() == DriveMode::Velocity);
        sim->advance(0.5);
        QVERIFY(ready.wait(2000));
        const QByteArray moving = d->readAll();
        QVERIFY2(moving.contains("\nIP7,"), moving.constData());
        QVERIFY2(moving.contains("CR12,10000.00\n"), moving.constData());
        QVERIFY2(moving.contains("GS258\n"), moving.constData());
    }

    // On the wall clock a simulator nobody talks to does nothing: no tick,
    // not a step of the physics. A query catches it up from the wall time
    // that passed, and the answer is where the rotator has got to.
    void aSimulatorLeftAloneRunsNothingAndCatchesUpWhenAsked()
    {
        auto link = openLink("sim:?time_scale=20");
        QVERIFY(link);
        Simulator *sim = simulatorBehind(link.get());
        QSignalSpy ticks(sim, &Simulator::ticked);
        QSignalSpy advanced(&sim->clock(), &SimClock::advanced);
        link->device()->write("AZ30.0 EL20.0\n"); // a go-to: no answer
        settle();
        QCOMPARE(sim->rotator().axis(Axis::Azimuth).targetPosition(), 30.0);
        const double ranTo = sim->rotator().time();
        // 20 simulated seconds: a G-5500 needs about 8 for that move.
        QVERIFY(letWallTimePass(1000));
        QCOMPARE(ticks.count(), 0);
        QCOMPARE(advanced.count(), 0);
        QCOMPARE(sim->rotator().time(), ranTo);
        const QByteArray reply = ask(link.get(), "AZ EL\n");
        const QList<QByteArray> words = reply.trimmed().split(' ');
        QCOMPARE(words.size(), 2);
        QVERIFY2(std::abs(words[0].mid(2).toDouble() - 30.0) <= AxisModel::settleTolerance, reply.constData());
        QVERIFY2(std::abs(words[1].mid(2).toDouble() - 20.0) <= AxisModel::settleTolerance, reply.constData());
        QVERIFY(sim->rotator().time() >= ranTo + 19.0);
        QCOMPARE(ticks.count(), 0);
    }

    // Pushes need the rotator run while it changes, so a connection that
    // wants them gets ticks then, and none once all is at rest.
    void unsolicitedPushesTickOnlyWhileSomethingChanges()
    {
        auto link = openLink("sim:?unsolicited=1&time_scale=4");
        QVERIFY(link);
        Simulator *sim = simulatorBehind(link.get());
        QIODevice *d = link->device();
        QSignalSpy ready(d, &QIODevice::readyRead);
        QByteArray seen;
        while (!seen.contains("VESlewSim")) {
            QVERIFY(d->bytesAvailable() > 0 || ready.wait(2000));
            seen += d->readAll();
        }
        QVERIFY2(seen.startsWith("AZ0.00\nEL0.00\nIP0,25.00\n"), seen.constData());
        QSignalSpy ticks(sim, &Simulator::ticked);
        QVERIFY(letWallTimePass(300));
        QCOMPARE(ticks.count(), 0);
        d->write("AZ2.0\n");
        seen.clear();
        while (!seen.contains("AZ2.00\n")) {
            QVERIFY(d->bytesAvailable() > 0 || ready.wait(5000));
            seen += d->readAll();
        }
        // The way there was pushed too, a tick at a time.
        QVERIFY2(seen.contains("AZ1."), seen.constData());
        QVERIFY(ticks.count() >= 2);
    }

    void faultsSwitchAtRunTime()
    {
        auto link = openLink("sim:?clock=manual&jam=az&jam_after=0.5");
        QVERIFY(link);
        Simulator *sim = simulatorBehind(link.get());
        QCOMPARE(ask(link.get(), "AZ50\nGE\n"), QByteArray("GE1\n"));
        sim->advance(1.0);
        QCOMPARE(ask(link.get(), "GE\nGS\n"), QByteArray("GE8\nGS264\n"));
        sim->setAxisFaults(Axis::Azimuth, {});
        QCOMPARE(ask(link.get(), "RESET\nGE\n"), QByteArray("GE1\n"));
    }
};

QTEST_GUILESS_MAIN(TestSimulatorLink)
#include "tst_simulatorlink.moc"
