// SPDX-License-Identifier: GPL-3.0-or-later
// The tracker on the simulator's manual clock: a whole pass in about a
// second of test time. It arrives at the AOS point early, follows the plan
// inside the limits, sends fewer than one command a second, parks after
// LOS, and a stop from anywhere ends it at once; a step of the station
// clock is seen at once, not at the end of a long wait.

#include "../common/simulatorpump.h"
#include "linkschemes.h"
#include "protocol/parser.h"
#include "session/rotatorsession.h"
#include "sim/simulator.h"
#include "sim/simulatorscheme.h"
#include "syntheticpass.h"
#include "tracking/leastworstswing.h"
#include "tracking/rotatorreach.h"
#include "tracking/tracker.h"

#include <QSignalSpy>
#include <QTest>

using slew::session::RotatorSession;
using namespace slew::tracking;

namespace {

struct Rig {
    RotatorSession session;
    SimulatorPump pump{0.02};
    slew::sim::Simulator *sim = nullptr;
    RotatorReach reach;
    QList<QPointF> targets; // every go-to the session sent, in mechanical positions

    bool open(double azMax, double elMax, double azOffset = 0, double elOffset = 0)
    {
        slew::model::RotatorProfile profile;
        profile.limits = slew::model::RotatorLimits{0, azMax, 0, elMax};
        profile.parkAz = 180;
        profile.parkEl = 90;
        profile.azOffsetDeg = azOffset;
        profile.elOffsetDeg = elOffset;
        session.setProfile(profile);
        // The controller's park registers (CW7/CW8) agree with the profile:
        // Park drives where the controller says, which the session reads.
        session.connectTo(QStringLiteral("sim:?clock=manual&az_max=%1&el_max=%2&park_az=180&park_el=90").arg(azMax).arg(elMax));
        pump.follow(&session);
        QObject::connect(&session, &RotatorSession::targetChanged, &session,
                         [this](double az, double el) { targets.append(QPointF(az, el)); });
        if (!runEventLoopUntil([&] { return session.capabilities().probed && session.hasPosition(); }, 10000))
            return false;
        sim = slew::sim::simulatorBehind(session.link());
        // The profile's motion is the G-5500 class simulator's (docs/simulator.md).
        reach = reachOf(session);
        return sim != nullptr;
    }

    // A station clock that keeps the simulator's: AOS `lead` simulated seconds from now.
    std::function<double()> clockWithAosIn(double lead, double aosJulian)
    {
        const double startSim = sim->clock().now();
        return [this, startSim, lead, aosJulian] {
            return aosJulian + (sim->clock().now() - startSim - lead) / 86400.0;
        };
    }
};

constexpr double kAos = 2461000.5; // any Julian date: the pass is made up

// After LOS the antenna stays, so the last go-to is the pass's own.
void stayAfterThePass(Tracker &tracker)
{
    TrackerSettings settings;
    settings.afterPass = TrackerSettings::AfterPass::Stay;
    tracker.setSettings(settings);
}

} // namespace

class TrackerTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { slew::registerLinkSchemes(); }

    void followsAPassOverTheNorthStopWithTheOverlap()
    {
        Rig rig;
        QVERIFY(rig.open(450, 180));
        const QList<SkyPoint> pass = greatCirclePass(0, 40, true); // north-west to north-east
        Tracker tracker(&rig.session);
        QSignalSpy states(&tracker, &Tracker::stateChanged);
        std::optional<double> errorAtAos;
        connect(&tracker, &Tracker::pointingError, this, [&](double deg, double) {
            if (!errorAtAos)
                errorAtAos = deg;
        });
        QVERIFY2(tracker.track(pass, kAos, rig.reach, rig.clockWithAosIn(120, kAos)), qPrintable(tracker.error()));
        QCOMPARE(tracker.state(), Tracker::State::Waiting);
        QVERIFY(!tracker.plan().flipped); // the overlap takes the crossing
        QVERIFY(tracker.plan().usesOverlap);

        QVERIFY(runEventLoopUntil([&] { return tracker.state() == Tracker::State::Done; }, 30000));
        const TrackingFigures &f = tracker.figures();
        qInfo("north crossing, 450/180: RMS %.3f°, worst %.3f°, %d commands in %.0f s (%.2f/s), %d samples",
              f.rmsDeg, f.worstDeg, f.commands, f.passSeconds, f.commandsPerSecond(), f.samples);
        // It was at the AOS point when the pass began.
        QVERIFY(errorAtAos && *errorAtAos < 1.0);
        QVERIFY(f.samples > 100);
        QVERIFY2(f.rmsDeg < 0.2, qPrintable(QString::number(f.rmsDeg)));
        QVERIFY2(f.worstDeg < 1.0, qPrintable(QString::number(f.worstDeg)));
        QVERIFY(f.commandsPerSecond() < 1.0);
        // Every command inside the travel, no unwind: never more than half a
        // turn between two (the park after LOS aside).
        for (int i = 0; i + 1 < rig.targets.size(); ++i) {
            QVERIFY(rig.targets[i].x() >= 0 && rig.targets[i].x() <= 450);
            QVERIFY(rig.targets[i].y() >= 0 && rig.targets[i].y() <= 180);
            if (i > 0)
                QVERIFY(std::abs(rig.targets[i].x() - rig.targets[i - 1].x()) < 180);
        }
        // After LOS it parks.
        QCOMPARE(rig.targets.last(), QPointF(180, 90));
        QCOMPARE(states.last().at(0).value<Tracker::State>(), Tracker::State::Done);
    }

    void reachesItsAosPointWhereTheOverlapOffersTwo()
    {
        // The antenna stands at 300° (a pass before left it there). The next
        // pass rises in the north-east and sets in the south-west: on a 450°
        // rotator only its angles from 0° can follow it to the end (from
        // 360° the travel runs out at 450°), so the plan starts there. The
        // simulator, like the Micro-2g program, takes a bearing below 360° to
        // the nearer of its two angles: asked for it at once, it would go to
        // the one in the overlap. A waypoint only one angle has comes first.
        Rig rig;
        QVERIFY(rig.open(450, 180));
        QVERIFY(rig.session.gotoUnwrapped(300, 10));
        QVERIFY(runEventLoopUntil([&] { return std::abs(rig.session.azimuth() - 300) < 0.5; }, 30000));
        const QList<SkyPoint> pass = greatCirclePass(110, 40, true);
        Tracker tracker(&rig.session);
        stayAfterThePass(tracker);
        std::optional<double> errorAtAos;
        connect(&tracker, &Tracker::pointingError, this, [&](double deg, double) {
            if (!errorAtAos)
                errorAtAos = deg;
        });
        rig.targets.clear();
        QVERIFY2(tracker.track(pass, kAos, rig.reach, rig.clockWithAosIn(150, kAos)), qPrintable(tracker.error()));
        QVERIFY2(tracker.plan().path.front().azimuth < 90, qPrintable(tracker.plan().describe()));
        QVERIFY(runEventLoopUntil([&] { return tracker.state() == Tracker::State::Done; }, 30000));
        QVERIFY(errorAtAos && *errorAtAos < 1.0);
        QVERIFY2(tracker.figures().worstDeg < 1.0, qPrintable(QString::number(tracker.figures().worstDeg)));
        QVERIFY(!rig.targets.isEmpty());
        QVERIFY2(rig.targets.first().x() > 90 && rig.targets.first().x() < 360,
                 qPrintable(QString::number(rig.targets.first().x()))); // the waypoint
        for (const QPointF &t : std::as_const(rig.targets))
            QVERIFY2(t.x() <= 360, qPrintable(QString::number(t.x()))); // never into the overlap
    }

    void followsAPassWithCalibrationOffsets()
    {
        // A rotator whose readings are 4° east and 1.5° high of where the
        // antenna points: the plan, the commands and the error all work in
        // where it points, and the controller gets its own angles.
        Rig rig;
        QVERIFY(rig.open(450, 180, 4.0, -1.5));
        QCOMPARE(rig.reach.limits.azMin, 4.0);
        QCOMPARE(rig.reach.limits.elMax, 178.5);
        QSignalSpy sent(&rig.session, &RotatorSession::bytesSent);
        Tracker tracker(&rig.session);
        QVERIFY(tracker.track(greatCirclePass(0, 40, true), kAos, rig.reach, rig.clockWithAosIn(120, kAos)));
        QVERIFY(runEventLoopUntil([&] { return tracker.state() == Tracker::State::Done; }, 30000));
        const TrackingFigures &f = tracker.figures();
        qInfo("north crossing, 450/180, offsets +4/-1.5: RMS %.3f°, worst %.3f°", f.rmsDeg, f.worstDeg);
        QVERIFY2(f.rmsDeg < 0.2 && f.worstDeg < 1.0, qPrintable(QStringLiteral("%1 %2").arg(f.rmsDeg).arg(f.worstDeg)));
        // The last go-to of the pass, as sent and as the session names it.
        const QPointF named = rig.targets[rig.targets.size() - 2];
        slew::protocol::Parser parser(rig.session.profile().dialect);
        std::optional<QPointF> wire;
        std::optional<double> az;
        for (const auto &args : sent)
            parser.feed(args.at(0).toByteArray(), [&](const slew::protocol::Message &m) {
                if (m.op == slew::protocol::Op::Azimuth && m.hasValue)
                    az = m.value;
                if (m.op == slew::protocol::Op::Elevation && m.hasValue && az && !(*az == 180 && m.value == 90))
                    wire = QPointF(*az, m.value);
            });
        QVERIFY(wire);
        QVERIFY2(std::abs(wire->x() - (named.x() - 4.0)) < 0.011 && std::abs(wire->y() - (named.y() + 1.5)) < 0.011,
                 qPrintable(QStringLiteral("%1/%2 sent for %3/%4").arg(wire->x()).arg(wire->y()).arg(named.x()).arg(named.y())));
    }

    void settingsFollowTheProfilesMotion()
    {
        slew::model::RotatorMotion motion;
        motion.responseDelayS = 0.8;
        TrackerSettings base;
        base.afterPass = TrackerSettings::AfterPass::Stay;
        TrackerSettings s = trackerSettingsFor(motion, base);
        // The delay, and 0.41 s for a 0.5° step at 12°/s² (never at full speed).
        QVERIFY(std::abs(s.leadSeconds - (0.8 + 2 * std::sqrt(0.5 / 12.0))) < 1e-9);
        QCOMPARE(s.minimumStepDeg, kServoMinimumStepDeg);
        QCOMPARE(s.afterPass, TrackerSettings::AfterPass::Stay); // kept from the base
        motion.drive = slew::model::RotatorMotion::Drive::Relay;
        QCOMPARE(trackerSettingsFor(motion).minimumStepDeg, kRelayMinimumStepDeg);
        motion.trackStepDeg = 1.25; // the operator's own step wins
        QCOMPARE(trackerSettingsFor(motion).minimumStepDeg, 1.25);
        // A long step reaches full speed: 10° at 6.2°/s and 12°/s².
        QVERIFY(std::abs(stepSeconds(10, 6.2, 12) - (10 / 6.2 + 6.2 / 12)) < 1e-9);
        QCOMPARE(stepSeconds(3, 6, 0), 0.5);
    }

    void theFlipOnA360Rotator()
    {
        Rig rig;
        QVERIFY(rig.open(360, 180));
        Tracker tracker(&rig.session);
        stayAfterThePass(tracker);
        // From the horizon to 180° of elevation takes 67 s at 2.7°/s: AOS is far enough off.
        QVERIFY(tracker.track(greatCirclePass(0, 40, true), kAos, rig.reach, rig.clockWithAosIn(120, kAos)));
        QVERIFY(tracker.plan().flipped);
        QVERIFY(runEventLoopUntil([&] { return tracker.state() == Tracker::State::Done; }, 30000));
        const TrackingFigures &f = tracker.figures();
        qInfo("north crossing, 360/180 (flip): RMS %.3f°, worst %.3f°, %.2f commands/s", f.rmsDeg, f.worstDeg,
              f.commandsPerSecond());
        QVERIFY(f.rmsDeg < 0.2 && f.worstDeg < 1.0);
        for (const QPointF &t : rig.targets)
            QVERIFY(t.y() >= 90); // over the top the whole pass
        // Stay: the last command is the pass's own.
        QVERIFY(rig.targets.last() != QPointF(180, 90));
    }

    // 0.5° from the zenith at a low orbit's 1° of sky a second: the sky's
    // bearing swings half a turn in about two seconds at the top. The
    // simulated G-5500 goes over the top instead, its azimuth barely moving.
    void overTheTopNearTheZenith()
    {
        Rig rig;
        QVERIFY(rig.open(450, 180));
        Tracker tracker(&rig.session);
        stayAfterThePass(tracker);
        QVERIFY(tracker.track(greatCirclePass(250, 89.5, false, 1.0, 1.0), kAos, rig.reach,
                              rig.clockWithAosIn(60, kAos)));
        QVERIFY2(tracker.plan().overTheTop, qPrintable(tracker.plan().describe()));
        QVERIFY(runEventLoopUntil([&] { return tracker.state() == Tracker::State::Done; }, 30000));
        const TrackingFigures &f = tracker.figures();
        qInfo("89.5° pass, 450/180 over the top: RMS %.3f°, worst %.3f°, %.2f commands/s", f.rmsDeg, f.worstDeg,
              f.commandsPerSecond());
        QVERIFY(f.rmsDeg < 0.2 && f.worstDeg < 1.0);
        double azLow = 1e9, azHigh = -1e9, elLow = 1e9, elHigh = -1e9;
        for (const QPointF &t : rig.targets) {
            azLow = std::min(azLow, t.x());
            azHigh = std::max(azHigh, t.x());
            elLow = std::min(elLow, t.y());
            elHigh = std::max(elHigh, t.y());
        }
        QVERIFY2(azHigh - azLow < 45.0, qPrintable(QStringLiteral("azimuth commanded over %1°").arg(azHigh - azLow)));
        QVERIFY(elLow < 5.0 && elHigh > 175.0); // horizon to horizon through the zenith
    }

    void aStopEndsTrackingAtOnce()
    {
        Rig rig;
        QVERIFY(rig.open(450, 180));
        Tracker tracker(&rig.session);
        QVERIFY(tracker.track(greatCirclePass(90, 50, true), kAos, rig.reach, rig.clockWithAosIn(30, kAos)));
        QVERIFY(runEventLoopUntil([&] { return tracker.secondsFromAos() > 60; }, 10000));
        QCOMPARE(tracker.state(), Tracker::State::Tracking);
        QVERIFY(rig.session.stop(QStringLiteral("the test"))); // the window's Stop, Space, Esc, rotctld S, shutdown: all end here
        QCOMPARE(tracker.state(), Tracker::State::Idle);
        const qsizetype sent = rig.targets.size();
        const double then = rig.sim->clock().now();
        QVERIFY(runEventLoopUntil([&] { return rig.sim->clock().now() > then + 20; }, 10000));
        QCOMPARE(rig.targets.size(), sent); // nothing more went out
    }

    void aStepOfTheClockIsSeenAtOnce()
    {
        Rig rig;
        QVERIFY(rig.open(450, 180));
        Tracker tracker(&rig.session);
        // An hour before AOS the tracker waits 30 s between looks; a paused
        // rehearsal then stepped to ten seconds before AOS.
        double stepped = 0;
        const std::function<double()> station = rig.clockWithAosIn(3600, kAos);
        QVERIFY(tracker.track(greatCirclePass(90, 50, true), kAos, rig.reach,
                              [&] { return station() + stepped / 86400.0; }));
        const double then = rig.sim->clock().now();
        QVERIFY(runEventLoopUntil([&] { return rig.sim->clock().now() > then + 2; }, 10000));
        QCOMPARE(tracker.state(), Tracker::State::Waiting);
        QVERIFY(!tracker.hasRotator());
        stepped = 3590;
        tracker.lookAgain();
        // On its way to the AOS point now, not half a minute later.
        QVERIFY(tracker.hasRotator());
        QVERIFY(!rig.targets.isEmpty());
    }

    void aLostLinkEndsTracking()
    {
        Rig rig;
        QVERIFY(rig.open(450, 180));
        Tracker tracker(&rig.session);
        QVERIFY(tracker.track(greatCirclePass(90, 50, true), kAos, rig.reach, rig.clockWithAosIn(30, kAos)));
        QSignalSpy states(&tracker, &Tracker::stateChanged);
        rig.session.disconnectFromRotator();
        QCOMPARE(tracker.state(), Tracker::State::Idle);
        QVERIFY(states.last().at(1).toString().contains(QStringLiteral("link")));
    }

    void refusesWithoutALinkOrAPlan()
    {
        RotatorSession session;
        Tracker tracker(&session);
        QVERIFY(!tracker.track(greatCirclePass(90, 50, true), kAos, RotatorReach{}, [] { return kAos; }));
        QVERIFY(tracker.error().contains(QStringLiteral("not connected")));
        Rig rig;
        QVERIFY(rig.open(450, 180));
        Tracker planless(&rig.session);
        QVERIFY(!planless.track({}, kAos, rig.reach, [] { return kAos; }));
        QVERIFY(!planless.error().isEmpty());
    }

    // The same kind of pass on a 360°/90° rotator must swing the azimuth
    // half a turn. The planner takes the swing the least-worst way; the
    // simulated G-5500 then lags by what the plan said before AOS, and
    // within a little of the floor no path at its rate can beat.
    void theZenithSwingOnA360Rotator()
    {
        Rig rig;
        QVERIFY(rig.open(360, 90));
        Tracker tracker(&rig.session);
        stayAfterThePass(tracker);
        const QList<SkyPoint> pass = greatCirclePass(250, 89.0, false, 0.55, 1.0);
        QVERIFY(tracker.track(pass, kAos, rig.reach, rig.clockWithAosIn(60, kAos)));
        QVERIFY(!tracker.plan().flipped && !tracker.plan().overTheTop);
        QCOMPARE(tracker.plan().unwinds, 0);
        QVERIFY(runEventLoopUntil([&] { return tracker.state() == Tracker::State::Done; }, 30000));
        const TrackingFigures &f = tracker.figures();
        const double floor = leastWorstFloorDeg(pass, rig.reach.azimuthRateDegS);
        qInfo("89° pass, 360/90: floor %.2f°, predicted %.2f°, measured worst %.2f° (RMS %.3f°), %.2f commands/s", floor,
              tracker.plan().predictedWorstDeg, f.worstDeg, f.rmsDeg, f.commandsPerSecond());
        QVERIFY(floor > 1.0);
        QVERIFY(std::abs(f.worstDeg - tracker.plan().predictedWorstDeg) < 0.5);
        QVERIFY2(f.worstDeg < floor + 0.5, qPrintable(QString::number(f.worstDeg)));
        // Every go-to within the travel.
        for (const QPointF &t : rig.targets)
            QVERIFY(t.x() >= 0 && t.x() <= 360 && t.y() >= 0 && t.y() <= 90);
    }

    void predictedLagOnA360Rotator()
    {
        // 360°/90° and a pass over the north stop: the plan unwinds and says
        // how far behind it will be; the rotator then is about that far behind.
        Rig rig;
        QVERIFY(rig.open(360, 90));
        Tracker tracker(&rig.session);
        QVERIFY(tracker.track(greatCirclePass(0, 40, true), kAos, rig.reach, rig.clockWithAosIn(60, kAos)));
        QCOMPARE(tracker.plan().unwinds, 1);
        QVERIFY(!tracker.plan().followable());
        QVERIFY(runEventLoopUntil([&] { return tracker.state() == Tracker::State::Done; }, 30000));
        const TrackingFigures &f = tracker.figures();
        qInfo("north crossing, 360/90 (unwind): predicted worst %.2f°, measured %.2f° (RMS %.2f°)",
              tracker.plan().predictedWorstDeg, f.worstDeg, f.rmsDeg);
        QVERIFY(f.worstDeg > 20);
        // The plan's prediction, made before AOS, holds to half a degree.
        QVERIFY(std::abs(f.worstDeg - tracker.plan().predictedWorstDeg) < 0.5);
    }
};

QTEST_MAIN(TrackerTest)
#include "tst_tracker.moc"
