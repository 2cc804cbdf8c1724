// SPDX-License-Identifier: GPL-3.0-or-later
// The tuning engine against a deliberately mistuned simulator on a stepped
// clock: the proposal must take the overshoot under 5 % and cut the settling
// time by at least 30 % on both axes, and cancel must leave the registers.
// A simulator run faster than real time (a rehearsal's pace) is not tuned
// or measured, and a run it speeds up midway is discarded.
#include "../common/simulatorpump.h"

#include "linkschemes.h"
#include "session/rotatorsession.h"
#include "sim/simulatorscheme.h"
#include "transport/link.h"
#include "tuning/axistuner.h"
#include "tuning/motionrun.h"

#include <QSignalSpy>
#include <QTest>

using namespace slew;
using session::Axis;
using session::RotatorSession;
using tuning::AxisTuner;
using tuning::TuningResult;

namespace {

// kp 12 with almost no damping: a 4° step overshoots by about half.
const QString kMistuned = QStringLiteral("sim:?clock=manual&unsolicited=1&kp=12&ki=1&kd=1&start_az=100&start_el=30");

sim::PidGains simGains(RotatorSession &s, Axis axis)
{
    return sim::simulatorBehind(s.link())
        ->rotator()
        .axis(axis == Axis::Azimuth ? sim::Axis::Azimuth : sim::Axis::Elevation)
        .gains();
}

} // namespace

class TestAxisTuner : public QObject {
    Q_OBJECT

    std::unique_ptr<RotatorSession> m_session;
    std::unique_ptr<SimulatorPump> m_pump;

    void connectTo(const QString &uri) { QVERIFY(connectPumped(uri, m_session, m_pump)); }

private slots:
    void initTestCase() { registerLinkSchemes(); }
    void cleanup()
    {
        m_pump.reset();
        m_session.reset();
    }

    void proposalFixesMistunedAxis_data()
    {
        QTest::addColumn<int>("axisIndex");
        QTest::newRow("azimuth") << int(Axis::Azimuth);
        QTest::newRow("elevation") << int(Axis::Elevation);
    }
    void proposalFixesMistunedAxis()
    {
        QFETCH(int, axisIndex);
        const Axis axis = Axis(axisIndex);
        connectTo(kMistuned);
        if (QTest::currentTestFailed())
            return;
        AxisTuner tuner(m_session.get());
        QSignalSpy ready(&tuner, &AxisTuner::resultReady);
        QSignalSpy failed(&tuner, &AxisTuner::failed);
        QVERIFY2(tuner.start(axis), qPrintable(tuner.error()));
        TRY_VERIFY2_WITH_TIMEOUT(ready.count() == 1 || failed.count() == 1, "no result", 60000);
        QVERIFY2(failed.isEmpty(), failed.isEmpty() ? "" : qPrintable(failed.front().front().toString()));
        const TuningResult r = tuner.result();
        qInfo().noquote() << "\n" << tuning::formatTuningTable({r});
        QCOMPARE(r.oldGains.kp, 12.0);
        QVERIFY2(r.beforeMetrics.overshootPercent > 20.0, qPrintable(QString::number(r.beforeMetrics.overshootPercent)));
        QVERIFY2(r.afterMetrics.overshootPercent < 5.0, qPrintable(QString::number(r.afterMetrics.overshootPercent)));
        QVERIFY(r.beforeMetrics.settled || r.beforeMetrics.settlingTime > 0);
        QVERIFY(r.afterMetrics.settled);
        QVERIFY2(r.afterMetrics.settlingTime <= 0.7 * r.beforeMetrics.settlingTime,
                 qPrintable(QStringLiteral("%1 vs %2").arg(r.afterMetrics.settlingTime).arg(r.beforeMetrics.settlingTime)));
        // The trial gains are on the controller until the operator decides.
        QCOMPARE(simGains(*m_session, axis).kp, r.newGains.kp);
        QSignalSpy finished(&tuner, &AxisTuner::finished);
        tuner.accept();
        QCOMPARE(finished.count(), 1);
        QVERIFY(tuner.result().applied);
        QCOMPARE(simGains(*m_session, axis).kd, r.newGains.kd);
    }

    void keepOldGainsWritesThemBack()
    {
        connectTo(kMistuned);
        if (QTest::currentTestFailed())
            return;
        AxisTuner tuner(m_session.get());
        QSignalSpy ready(&tuner, &AxisTuner::resultReady);
        QVERIFY(tuner.start(Axis::Azimuth));
        TRY_COMPARE_WITH_TIMEOUT(ready.count(), 1, 60000);
        QVERIFY(simGains(*m_session, Axis::Azimuth).kd != 1.0);
        QSignalSpy finished(&tuner, &AxisTuner::finished);
        tuner.keepOldGains();
        TRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 10000);
        QVERIFY(!tuner.result().applied);
        const sim::PidGains g = simGains(*m_session, Axis::Azimuth);
        QCOMPARE(g.kp, 12.0);
        QCOMPARE(g.ki, 1.0);
        QCOMPARE(g.kd, 1.0);
    }

    void cancelDuringTrialStopsAndRestores()
    {
        connectTo(kMistuned);
        if (QTest::currentTestFailed())
            return;
        AxisTuner tuner(m_session.get());
        QSignalSpy cancelled(&tuner, &AxisTuner::cancelled);
        QVERIFY(tuner.start(Axis::Elevation));
        // Cancel in the middle of the trial step, with the new gains written.
        int afterSamples = 0;
        connect(&tuner, &AxisTuner::sampleRecorded, this, [&](bool after, const tuning::PositionSample &) {
            if (after && ++afterSamples == 5) {
                QVERIFY(simGains(*m_session, Axis::Elevation).kd != 1.0);
                tuner.cancel();
            }
        });
        TRY_COMPARE_WITH_TIMEOUT(cancelled.count(), 1, 10000);
        const sim::PidGains g = simGains(*m_session, Axis::Elevation);
        QCOMPARE(g.kp, 12.0);
        QCOMPARE(g.ki, 1.0);
        QCOMPARE(g.kd, 1.0);
        // SE went out: the elevation drive is released (or held at zero speed).
        QVERIFY(sim::simulatorBehind(m_session->link())->rotator().axis(sim::Axis::Elevation).isStopped());
    }

    void badStartChangesNothing()
    {
        RotatorSession idle;
        AxisTuner tuner(&idle);
        QVERIFY(!tuner.start(Axis::Azimuth));
        QVERIFY(tuner.error().contains(QStringLiteral("connect")));

        connectTo(kMistuned);
        if (QTest::currentTestFailed())
            return;
        AxisTuner big(m_session.get());
        tuning::TuningSettings s;
        s.amplitude = 500;
        big.setSettings(s);
        QSignalSpy sent(m_session.get(), &RotatorSession::bytesSent);
        QVERIFY(!big.start(Axis::Elevation));
        QVERIFY2(big.error().contains(QStringLiteral("does not fit")), qPrintable(big.error()));
        for (const QList<QVariant> &bytes : sent)
            QVERIFY(!bytes.front().toByteArray().startsWith("EL"));
    }

    void refusesFasterThanRealTime()
    {
        // On the wall clock, as operators run it, at five times real time:
        // what the Time controller's rehearsal does to the built-in simulator.
        connectTo(QStringLiteral("sim:?unsolicited=1&kp=12&ki=1&kd=1&start_az=100&start_el=30"));
        if (QTest::currentTestFailed())
            return;
        QVERIFY(m_session->link()->setTimeScale(5.0));
        QCOMPARE(m_session->link()->timeScale(), 5.0);
        QSignalSpy sent(m_session.get(), &RotatorSession::bytesSent);
        AxisTuner tuner(m_session.get());
        QVERIFY(!tuner.start(Axis::Azimuth));
        QVERIFY2(tuner.error().startsWith(QStringLiteral("not tuned: the simulator runs 5 times faster than real time, "
                                                         "with a rehearsal's station clock")),
                 qPrintable(tuner.error()));
        QVERIFY(tuner.error().endsWith(QStringLiteral("Put the station clock back to real time to measure")));
        tuning::MotionRun speed(m_session.get());
        QVERIFY(!speed.start(Axis::Elevation));
        QVERIFY2(speed.error().startsWith(QStringLiteral("speed not measured: the simulator runs 5 times faster")),
                 qPrintable(speed.error()));
        // Nothing moved, and no register was read or written.
        for (const QList<QVariant> &bytes : sent) {
            const QByteArray b = bytes.front().toByteArray();
            QVERIFY2(!b.startsWith("AZ") && !b.startsWith("EL") && !b.startsWith("CR") && !b.startsWith("CW"), b.constData());
        }
    }

    void discardsARunSpedUpMidway()
    {
        connectTo(QStringLiteral("sim:?unsolicited=1&kp=12&ki=1&kd=1&start_az=100&start_el=30"));
        if (QTest::currentTestFailed())
            return;
        const sim::PidGains before = simGains(*m_session, Axis::Azimuth);
        AxisTuner tuner(m_session.get());
        QSignalSpy failed(&tuner, &AxisTuner::failed);
        QSignalSpy offered(&tuner, &AxisTuner::resultReady);
        QVERIFY2(tuner.start(Axis::Azimuth), qPrintable(tuner.error()));
        // A rehearsal starts while the step runs.
        QVERIFY(m_session->link()->setTimeScale(5.0));
        QVERIFY(failed.wait(60000));
        QVERIFY2(failed.front().front().toString().startsWith(
                     QStringLiteral("the measurement is discarded: the simulator runs 5 times faster")),
                 qPrintable(failed.front().front().toString()));
        QCOMPARE(offered.count(), 0);
        QVERIFY(!tuner.isRunning());
        const sim::PidGains after = simGains(*m_session, Axis::Azimuth);
        QCOMPARE(after.kp, before.kp);
        QCOMPARE(after.ki, before.ki);
        QCOMPARE(after.kd, before.kd);
    }
};

QTEST_GUILESS_MAIN(TestAxisTuner)
#include "tst_axistuner.moc"
