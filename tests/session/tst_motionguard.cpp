// SPDX-License-Identifier: GPL-3.0-or-later
// The motion guard (session/motionguard.h): its judgement on readings given
// by hand (no motion, the wrong way, a drive turned round that coasts on,
// a controller's deadband, a tracker's stream of targets), then a session
// on the simulator in GS-232B, a dialect with no status register, with a
// jammed azimuth and with a reversed motor: each is stopped within the
// guard's time and a poll, held, and free again once cleared. All on the
// simulator's manual clock, pumped through the event loop.

#include "../common/simulatorpump.h"
#include "linkschemes.h"
#include "protocol/parser.h"
#include "session/motionguard.h"
#include "session/rotatorsession.h"
#include "sim/simulator.h"
#include "sim/simulatorscheme.h"

#include <QSignalSpy>
#include <QTest>

using slew::session::Axis;
using slew::session::AxisMotionGuard;
using slew::session::MotionFault;
using slew::session::RotatorSession;

namespace {

// Readings every `step` seconds from `from` to `to` seconds, the position
// given by `at(t)`; the first fault, if any.
std::optional<MotionFault> run(AxisMotionGuard &g, double from, double to, const std::function<double(double)> &at,
                               double step = 0.2)
{
    for (double t = from; t <= to + 1e-9; t += step)
        if (const std::optional<MotionFault> f = g.reading(t, at(t)))
            return f;
    return std::nullopt;
}

} // namespace

class MotionGuardTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { slew::registerLinkSchemes(); }

    void judgesWhatItIsShown()
    {
        AxisMotionGuard g;
        // Turning at 6°/s to its target: arrived, nothing said.
        g.drive(0, 10, 100.0, 0, 1.0);
        QVERIFY(!run(g, 0, 20, [](double t) { return std::min(100.0, 10 + 6 * t); }));
        QVERIFY(!g.isDriven());
        // Jammed: not a tenth of a degree in 5 s.
        g.drive(0, 10, 100.0, 0, 1.0);
        std::optional<MotionFault> f = run(g, 0, 10, [](double) { return 10.05; });
        QVERIFY(f && f->kind == MotionFault::Kind::NoMotion);
        QVERIFY(f->seconds >= 5 && f->seconds < 5.3);
        QCOMPARE(slew::session::describeMotionFault(true, *f),
                 QStringLiteral("Azimuth did not move for 5.0 s while driven towards 100.0°, at 10.1°: stopped"));
        // Jammed half-way, far from the target: 5 s after it stopped.
        g.drive(0, 10, 100.0, 0, 1.0);
        f = run(g, 0, 20, [](double t) { return std::min(40.0, 10 + 6 * t); });
        QVERIFY(f && f->kind == MotionFault::Kind::NoMotion && std::abs(f->at - 40) < 1e-9);
        // The wrong way: a reversed motor runs away from the target.
        g.drive(0, 50, 100.0, 0, 1.0);
        f = run(g, 0, 10, [](double t) { return 50 - 6 * t; });
        QVERIFY(f && f->kind == MotionFault::Kind::Runaway);
        QVERIFY2(f->seconds >= 2 && f->seconds < 2.5, qPrintable(QString::number(f->seconds)));
        // Turned round at speed: it coasts on 5° the old way over 1.7 s,
        // then comes back. Not a runaway.
        g.drive(0, 50, 0.0, 0, 1.0);
        QVERIFY(!run(g, 0, 30, [](double t) {
            return t < 1.7 ? 50 + 6 * t - 1.8 * t * t : std::max(0.0, 55.0 - 6 * (t - 1.7));
        }));
        // A jog: driven up at 4°/s, then stuck.
        g.drive(0, 10, std::nullopt, +1, 1.0);
        f = run(g, 0, 20, [](double t) { return std::min(30.0, 10 + 4 * t); });
        QVERIFY(f && f->kind == MotionFault::Kind::NoMotion);
        const QString said = slew::session::describeMotionFault(false, *f);
        QVERIFY2(said.startsWith(QStringLiteral("Elevation did not move for 5."))
                     && said.endsWith(QStringLiteral(" s while driven up, at 30.0°: stopped")),
                 qPrintable(said));
        // Within a deadband of the target (a Micro-2g stops 6° short, or does
        // not start for a small step): not judged.
        g.drive(0, 54, 60.0, 0, 1.0);
        QVERIFY(!run(g, 0, 30, [](double) { return 54.0; }));
        QVERIFY(g.isDriven()); // until its next target, or a stop
        g.release();
        // A tracker's next target on the same side does not restart the time:
        // a jammed axis under a stream of targets is still seen.
        g.drive(0, 10, 40.0, 0, 1.0);
        for (int i = 1; i <= 30 && g.isDriven(); ++i) {
            f = g.reading(i * 0.25, 10.0);
            if (!f)
                g.drive(i * 0.25, 10.0, 40.0 + i * 0.1, 0, 1.0);
        }
        QVERIFY(f && f->kind == MotionFault::Kind::NoMotion);
        // The controller's own park, either way round: 360° is 0°.
        g.driveByController(0, 300, 0.0, 1.0);
        QVERIFY(!run(g, 0, 20, [](double t) { return std::min(360.0, 300 + 6 * t); }));
        QVERIFY(!g.isDriven());
        // Switched off: nothing is judged.
        slew::session::MotionGuardSettings off;
        off.enabled = false;
        g.setSettings(off);
        g.drive(0, 10, 100.0, 0, 1.0);
        QVERIFY(!g.isDriven());
    }

    void aJammedAzimuthIsStoppedAndHeld()
    {
        RotatorSession s;
        QVERIFY(open(s, QStringLiteral("jam=az")));
        QSignalSpy faults(&s, &RotatorSession::motionFaultChanged);
        QSignalSpy stops(&s, &RotatorSession::stopSent);
        const double sent = simSeconds(s);
        QVERIFY(s.gotoPosition(200, 30));
        TRY_VERIFY_WITH_TIMEOUT(!faults.isEmpty(), 20000);
        // Within the no-motion time and a poll (at most a second between them).
        QVERIFY2(simSeconds(s) - sent < 5.0 + 1.5, qPrintable(QString::number(simSeconds(s) - sent)));
        QCOMPARE(faults.first().at(0).value<Axis>(), Axis::Azimuth);
        QVERIFY2(faults.first().at(1).toString().startsWith(QStringLiteral("Azimuth did not move for 5")),
                 qPrintable(faults.first().at(1).toString()));
        QVERIFY(!stops.isEmpty());
        QCOMPARE(stops.last().at(0).toString(), QStringLiteral("the motion guard: the azimuth"));
        QVERIFY(s.hasMotionFault());
        // Held: every move that drives the azimuth is refused, with why.
        QSignalSpy written(&s, &RotatorSession::moveSent);
        const auto again = s.gotoPosition(150, 30);
        QVERIFY(!again);
        QVERIFY2(again.refusal.startsWith(QStringLiteral("the azimuth is held after the motion guard stopped it")),
                 qPrintable(again.refusal));
        QVERIFY(!s.moveAxis(Axis::Azimuth, 5));
        QVERIFY(!s.park());
        QCOMPARE(written.size(), 0);
        // The elevation alone, the azimuth left where it is: free to go.
        QVERIFY(s.gotoPosition(s.azimuth(), 20));
        QCOMPARE(written.size(), 1);
        // Stop always goes.
        QVERIFY(s.stop(QStringLiteral("the test")));
        // Cleared: the azimuth may be driven again.
        QSignalSpy cleared(&s, &RotatorSession::motionFaultsCleared);
        QVERIFY(s.clearMotionFaults(QStringLiteral("the test")));
        QCOMPARE(cleared.size(), 1);
        QVERIFY(!s.hasMotionFault());
        QVERIFY(!s.clearMotionFaults(QStringLiteral("the test"))); // nothing left to clear
        QVERIFY(s.gotoPosition(150, 30));
    }

    void aReversedMotorIsStoppedAsARunaway()
    {
        RotatorSession s;
        QVERIFY(open(s, QStringLiteral("reversed=el")));
        QSignalSpy faults(&s, &RotatorSession::motionFaultChanged);
        QVERIFY(s.gotoPosition(100, 60));
        TRY_VERIFY_WITH_TIMEOUT(!faults.isEmpty(), 20000);
        QCOMPARE(faults.first().at(0).value<Axis>(), Axis::Elevation);
        QVERIFY2(faults.first().at(1).toString().startsWith(QStringLiteral("Elevation ran the wrong way for 2")),
                 qPrintable(faults.first().at(1).toString()));
        // Stopped a few degrees below where it started (40°), not at its stop.
        QVERIFY2(s.elevation() > 30, qPrintable(QString::number(s.elevation())));
        QVERIFY(!s.gotoPosition(100, 70));
    }

    void aHealthySlewSaysNothing()
    {
        RotatorSession s;
        QVERIFY(open(s, QString()));
        QSignalSpy faults(&s, &RotatorSession::motionFaultChanged);
        QVERIFY(s.gotoPosition(300, 80));
        TRY_VERIFY_WITH_TIMEOUT(std::abs(s.azimuth() - 300) < 1 && std::abs(s.elevation() - 80) < 1, 60000);
        QVERIFY(s.gotoPosition(10, 5));
        TRY_VERIFY_WITH_TIMEOUT(std::abs(s.azimuth() - 10) < 1 && std::abs(s.elevation() - 5) < 1, 60000);
        QVERIFY(s.moveAxis(Axis::Azimuth, 5));
        const double t = simSeconds(s);
        QVERIFY(runEventLoopUntil([&] { return simSeconds(s) > t + 8; }, 20000));
        QVERIFY(s.stop(QStringLiteral("the test")));
        QCOMPARE(faults.size(), 0);
    }

    // SPID jogs by position legs, renewed while the key is held: at the end
    // of the travel the session stops the jog (the soft limit), and nothing
    // is driven into it. No stall is said.
    void aJogHeldAtTheEndOfTheTravelSaysNothing()
    {
        RotatorSession s;
        QVERIFY(open(s, QString(), QStringLiteral("rot2prog")));
        QSignalSpy faults(&s, &RotatorSession::motionFaultChanged);
        QVERIFY(s.moveAxis(Axis::Elevation, 10));
        const double held = simSeconds(s);
        QVERIFY(runEventLoopUntil([&] { return simSeconds(s) > held + 50; }, 60000));
        QVERIFY2(s.elevation() > 85, qPrintable(QString::number(s.elevation())));
        QCOMPARE(faults.size(), 0);
        QVERIFY(s.stop(QStringLiteral("the test")));
    }

private:
    // The simulator's own time, which the session's guard runs by.
    static double simSeconds(const RotatorSession &s) { return slew::sim::simulatorBehind(s.link())->clock().now(); }

    static bool open(RotatorSession &s, const QString &faults, const QString &dialect = QStringLiteral("gs232b"))
    {
        slew::model::RotatorProfile profile;
        profile.dialect = *slew::protocol::dialectFromName(dialect);
        s.setProfile(profile);
        s.connectTo(QStringLiteral("sim:?clock=manual&dialect=%1&start_az=100&start_el=40%2")
                        .arg(dialect, faults.isEmpty() ? QString() : QStringLiteral("&") + faults));
        (new SimulatorPump(0.005, &s))->follow(&s);
        return runEventLoopUntil([&] { return s.capabilities().probed && s.hasPosition(); }, 10000);
    }
};

QTEST_MAIN(MotionGuardTest)
#include "tst_motionguard.moc"
