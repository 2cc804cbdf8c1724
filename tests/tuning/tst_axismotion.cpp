// SPDX-License-Identifier: GPL-3.0-or-later
// The axis' speed, acceleration and response delay read off a recorded step
// (tuning/axismotion.h), on steps made up from known figures, as a poll at
// 10 Hz with encoder noise sees them; then measured on the simulated G-5500
// (tuning/motionrun.h) on its manual clock.

#include "../common/simulatorpump.h"
#include "linkschemes.h"
#include "session/rotatorsession.h"
#include "tuning/axismotion.h"
#include "tuning/motionrun.h"

#include <QSignalSpy>

#include <QRandomGenerator>
#include <QTest>

#include <cmath>

using namespace slew::tuning;

namespace {

// An axis that waits `delay`, speeds up at `accel` to `speed`, and brakes
// as hard onto the target; polled every `period` seconds.
StepResponse trapezoid(double amplitude, double delay, double speed, double accel, double period = 0.1,
                       double noise = 0.01)
{
    StepResponse r;
    r.start = 10.0;
    r.target = 10.0 + amplitude;
    const double direction = amplitude >= 0 ? 1 : -1;
    const double distance = std::abs(amplitude);
    const double rampTime = speed / accel;
    const double rampDistance = 0.5 * accel * rampTime * rampTime;
    QRandomGenerator noiseSource(7);
    const bool reachesSpeed = 2 * rampDistance < distance;
    const double peak = reachesSpeed ? speed : std::sqrt(accel * distance);
    const double up = peak / accel;
    const double cruise = reachesSpeed ? (distance - 2 * rampDistance) / speed : 0.0;
    const double total = delay + 2 * up + cruise;
    for (double t = 0; t <= total + 2.0; t += period) {
        double x = 0;
        const double m = t - delay;
        if (m <= 0)
            x = 0;
        else if (m < up)
            x = 0.5 * accel * m * m;
        else if (m < up + cruise)
            x = 0.5 * accel * up * up + peak * (m - up);
        else if (m < 2 * up + cruise) {
            const double b = 2 * up + cruise - m;
            x = distance - 0.5 * accel * b * b;
        } else
            x = distance;
        const double jitter = noise * (noiseSource.generateDouble() - 0.5) * 2;
        r.samples.append({t, r.start + direction * x + jitter});
    }
    r.duration = total + 2.0;
    return r;
}

} // namespace

class AxisMotionTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { slew::registerLinkSchemes(); }

    void measuresTheSimulatedG5500_data()
    {
        QTest::addColumn<int>("axis");
        QTest::addColumn<double>("speed");
        QTest::newRow("azimuth") << int(slew::session::Axis::Azimuth) << 6.2;
        QTest::newRow("elevation") << int(slew::session::Axis::Elevation) << 2.7;
    }
    void measuresTheSimulatedG5500()
    {
        QFETCH(int, axis);
        QFETCH(double, speed);
        std::unique_ptr<slew::session::RotatorSession> session;
        std::unique_ptr<SimulatorPump> pump;
        // Both start near their top, so the move goes down: the side with room.
        QVERIFY(connectPumped(QStringLiteral("sim:?clock=manual&start_az=340&start_el=80"), session, pump));
        MotionRun run(session.get());
        QSignalSpy measured(&run, &MotionRun::measured);
        QSignalSpy failed(&run, &MotionRun::failed);
        QVERIFY2(run.start(slew::session::Axis(axis)), qPrintable(run.error()));
        QVERIFY(runEventLoopUntil([&] { return !measured.isEmpty() || !failed.isEmpty(); }, 60000));
        QVERIFY2(failed.isEmpty(), failed.isEmpty() ? "" : qPrintable(failed.first().first().toString()));
        const AxisMotion m = measured.first().at(1).value<AxisMotion>();
        qInfo("speed %.2f°/s, accel %.1f°/s², delay %.2f s", m.speedDegS, m.accelDegS2, m.responseDelayS);
        QVERIFY(std::abs(m.speedDegS - speed) < 0.1);
        QVERIFY(m.responseDelayS < 0.5);
        QVERIFY(m.accelDegS2 > 2);
    }

    void refusesWithoutRoom()
    {
        std::unique_ptr<slew::session::RotatorSession> session;
        std::unique_ptr<SimulatorPump> pump;
        QVERIFY(connectPumped(QStringLiteral("sim:?clock=manual"), session, pump));
        slew::model::RotatorProfile narrow = session->profile();
        narrow.limits = slew::model::RotatorLimits{0, 360, 0, 20};
        narrow.parkEl = 10;
        session->setProfile(narrow);
        MotionRun run(session.get());
        QVERIFY(!run.start(slew::session::Axis::Elevation));
        QVERIFY2(run.error().contains(QStringLiteral("does not fit")), qPrintable(run.error()));
    }

    void aG5500Azimuth()
    {
        const AxisMotion m = measureAxisMotion(trapezoid(30, 0.3, 6.2, 12), 0.08);
        QVERIFY2(m.ok, qPrintable(m.error));
        qInfo("speed %.3f°/s, accel %.2f°/s², delay %.3f s", m.speedDegS, m.accelDegS2, m.responseDelayS);
        QVERIFY(std::abs(m.speedDegS - 6.2) < 0.1);
        QVERIFY(std::abs(m.responseDelayS - 0.3) < 0.1);
        QVERIFY(m.accelDegS2 > 8 && m.accelDegS2 < 18);
    }

    void anElevationDownwards()
    {
        const AxisMotion m = measureAxisMotion(trapezoid(-30, 0.5, 2.7, 6), 0.08);
        QVERIFY2(m.ok, qPrintable(m.error));
        QVERIFY(std::abs(m.speedDegS - 2.7) < 0.05);
        QVERIFY(std::abs(m.responseDelayS - 0.5) < 0.1);
    }

    void aShortStepIsNotTakenForTheSpeed()
    {
        // 2°: the axis is still getting up to speed when it must brake.
        const AxisMotion m = measureAxisMotion(trapezoid(2, 0.3, 6.2, 12), 0.08);
        QVERIFY(!m.ok);
        QVERIFY2(m.error.contains(QStringLiteral("too short")), qPrintable(m.error));
    }

    void anAxisThatDoesNotMove()
    {
        StepResponse r;
        r.start = 0;
        r.target = 30;
        for (int i = 0; i < 50; ++i)
            r.samples.append({i * 0.1, 0.0});
        const AxisMotion m = measureAxisMotion(r, 0.08);
        QVERIFY(!m.ok);
        QVERIFY(m.error.contains(QStringLiteral("did not move")));
    }
};

QTEST_MAIN(AxisMotionTest)
#include "tst_axismotion.moc"
