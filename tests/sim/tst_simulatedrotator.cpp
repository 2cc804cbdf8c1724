// SPDX-License-Identifier: GPL-3.0-or-later
// The whole rotator on a stepped clock: overlap paths, end stops, homing,
// park, registers, the rotator classes and their stop, and every fault as
// GS / GE / IP report it (Easycomm III derivative).
#include "sim/rotatormodels.h"
#include "sim/simulatedrotator.h"

#include <QTest>

#include <algorithm>
#include <cmath>

using namespace slew::sim;

namespace {

// Most cases here are about paths, switches and registers, not speed: they
// run on the fast SatNOGS-class preset so that they take little simulated time.
RotatorConfig fastConfig()
{
    RotatorConfig c;
    applyRotatorModel(c, *findRotatorModel(u"satnogs"));
    return c;
}

RotatorConfig withAzimuthRange(double maxDegrees, double start = 0.0)
{
    RotatorConfig c = fastConfig();
    c.azimuth.maxDegrees = maxDegrees;
    c.startAzimuth = start;
    return c;
}

// Advances in 25 ms ticks, recording the extremes of the true azimuth.
struct Span {
    double low = 1e9;
    double high = -1e9;
};
Span runAz(SimulatedRotator &r, double seconds)
{
    Span s;
    for (double t = 0; t < seconds; t += 0.025) {
        r.advanceBy(0.025);
        s.low = std::min(s.low, r.axis(Axis::Azimuth).antennaPosition());
        s.high = std::max(s.high, r.axis(Axis::Azimuth).antennaPosition());
    }
    return s;
}

int azByte(const SimulatedRotator &r) { return r.status() & 0xff; }
int elByte(const SimulatedRotator &r) { return r.status() >> 8; }

} // namespace

class TestSimulatedRotator : public QObject {
    Q_OBJECT
private slots:
    void tenDegreeStepSettlesWithinATenthOnBothAxes()
    {
        SimulatedRotator r(withAzimuthRange(360.0, 100.0));
        QVERIFY(r.pointAzimuth(110.0));
        QVERIFY(r.pointElevation(10.0));
        const Span s = runAz(r, 4.0);
        QVERIFY(std::fabs(r.axis(Axis::Azimuth).position() - 110.0) <= 0.1); // default gains
        QVERIFY(std::fabs(r.axis(Axis::Elevation).position() - 10.0) <= 0.1);
        QVERIFY(s.high < 110.2);
        QCOMPARE(r.status(), 4 | (4 << 8));
    }

    void overlapTakesTheShortestLegalPath_data()
    {
        QTest::addColumn<double>("azMax");
        QTest::addColumn<double>("start");
        QTest::addColumn<double>("command");
        QTest::addColumn<double>("arrival");
        QTest::newRow("350 to 10 through the overlap") << 450.0 << 350.0 << 10.0 << 370.0;
        QTest::newRow("420 to 10 stays in the overlap") << 450.0 << 420.0 << 10.0 << 370.0;
        QTest::newRow("80 to 5 goes back") << 450.0 << 80.0 << 5.0 << 5.0;
        QTest::newRow("200 to 80 the near way") << 450.0 << 200.0 << 80.0 << 80.0;
        QTest::newRow("no overlap: the long way round") << 360.0 << 350.0 << 10.0 << 10.0;
        QTest::newRow("explicit overlap angle") << 450.0 << 10.0 << 400.0 << 400.0;
    }
    void overlapTakesTheShortestLegalPath()
    {
        QFETCH(double, azMax);
        QFETCH(double, start);
        QFETCH(double, command);
        QFETCH(double, arrival);
        SimulatedRotator r(withAzimuthRange(azMax, start));
        QVERIFY(r.pointAzimuth(command));
        QCOMPARE(r.axis(Axis::Azimuth).targetPosition(), arrival);
        const Span s = runAz(r, 30.0);
        QVERIFY(std::fabs(r.axis(Axis::Azimuth).position() - arrival) <= 0.1);
        // It went straight there: never beyond either end of the path.
        QVERIFY(s.low >= std::min(start, arrival) - 0.3);
        QVERIFY(s.high <= std::max(start, arrival) + 0.3);
        QVERIFY(s.high <= azMax + 1.0);
        QCOMPARE(r.readRegister(10).value(), command);
    }

    void anglesOutsideTheLimitsMoveNothing()
    {
        SimulatedRotator r(withAzimuthRange(360.0, 50.0));
        QVERIFY(!r.pointAzimuth(360.5));
        QVERIFY(!r.pointAzimuth(-0.1));
        QVERIFY(!r.pointElevation(180.1));
        RotatorConfig c;
        c.elevation.maxDegrees = 90.0;
        SimulatedRotator low(c);
        QVERIFY(!low.pointElevation(90.5));
        QVERIFY(low.pointElevation(90.0));
        r.advanceBy(2.0);
        QCOMPARE(r.axis(Axis::Azimuth).position(), 50.0);
        QCOMPARE(r.axis(Axis::Azimuth).mode(), DriveMode::Released);
    }

    void velocityIntoAnEndStopStopsAtTheSwitch()
    {
        SimulatedRotator r(withAzimuthRange(360.0, 340.0));
        r.driveAzimuth(30000.0);
        const Span s = runAz(r, 5.0);
        QVERIFY(s.high <= 361.0);
        QCOMPARE(r.readInput(1).value(), 2.0); // CW limit
        r.driveAzimuth(-5000.0);
        r.advanceBy(1.0);
        QCOMPARE(r.readInput(1).value(), 0.0);
        QCOMPARE(r.readInput(2).value(), 1.0); // elevation rests on its lower switch
    }

    void homingTakesTimeAndEndsAtZero()
    {
        SimulatedRotator r(withAzimuthRange(450.0, 120.0));
        QVERIFY(r.pointElevation(45.0));
        r.advanceBy(5.0);
        r.reset();
        r.advanceBy(1.0);
        QCOMPARE(azByte(r), 2);
        QCOMPARE(elByte(r), 2);
        QCOMPARE(r.readRegister(9).value(), 3.0); // homing
        QVERIFY(r.axis(Axis::Azimuth).position() > 100.0);
        r.advanceBy(30.0);
        QCOMPARE(r.axis(Axis::Azimuth).position(), 0.0);
        QCOMPARE(r.axis(Axis::Elevation).position(), 0.0);
        QCOMPARE(r.status(), 4 | (4 << 8));
        QCOMPARE(r.errorRegister(), 1);
    }

    void parkGoesToTheParkRegisters()
    {
        SimulatedRotator r(withAzimuthRange(360.0, 10.0));
        QVERIFY(r.writeRegister(7, 180.0));
        QVERIFY(r.writeRegister(8, 90.0));
        QVERIFY(!r.writeRegister(8, 181.0));
        r.park();
        r.advanceBy(20.0);
        QVERIFY(std::fabs(r.axis(Axis::Azimuth).position() - 180.0) <= 0.1);
        QVERIFY(std::fabs(r.axis(Axis::Elevation).position() - 90.0) <= 0.1);
        QCOMPARE(r.readRegister(7).value(), 180.0);
    }

    void gainRegistersDriveTheLoops()
    {
        SimulatedRotator r(withAzimuthRange(360.0, 100.0));
        QVERIFY(r.writeRegister(1, 40.0)); // kp 40, ki 0, kd 0: undamped
        QVERIFY(r.writeRegister(2, 0.0));
        QVERIFY(r.writeRegister(3, 0.0));
        QVERIFY(!r.writeRegister(1, -1.0));
        QCOMPARE(r.readRegister(1).value(), 40.0);
        QCOMPARE(r.axis(Axis::Azimuth).gains().kp, 40.0);
        r.pointAzimuth(110.0);
        const Span s = runAz(r, 4.0);
        QVERIFY(s.high > 112.0); // more than 20 % overshoot with these gains
        QCOMPARE(r.readRegister(4).value(), 40.0); // elevation untouched
    }

    void temperatureRisesWithLoad()
    {
        SimulatedRotator r(fastConfig());
        r.driveAzimuth(30000.0);
        r.driveElevation(30000.0);
        r.advanceBy(2.0);
        QVERIFY(r.readInput(5).value() > 10.0);
        QVERIFY(r.readInput(6).value() > 10.0);
        QVERIFY(std::fabs(r.readInput(7).value() - 30.0) < 0.5);
        r.advanceBy(3.0);
        QVERIFY(r.readInput(0).value() > 25.1);
        QCOMPARE(r.readRegister(9).value(), 1.0); // velocity mode
    }

    void jamShowsAsAMotorError()
    {
        SimulatedRotator r(withAzimuthRange(360.0, 100.0));
        AxisFaults f;
        f.jam = true;
        r.setFaults(Axis::Azimuth, f);
        r.pointAzimuth(150.0);
        r.advanceBy(0.5);
        QCOMPARE(azByte(r), 6);
        r.advanceBy(1.0);
        QCOMPARE(azByte(r), 8);
        QCOMPARE(r.errorRegister(), 8);
        QCOMPARE(r.readInput(3).value(), 100.0);
        // RESET clears it once the jam is gone.
        r.setFaults(Axis::Azimuth, {});
        r.reset();
        r.advanceBy(1.0);
        QCOMPARE(r.errorRegister(), 1);
    }

    void encoderFaultsShowAsSensorErrors()
    {
        SimulatedRotator r(withAzimuthRange(360.0, 100.0));
        AxisFaults freeze;
        freeze.encoderFreeze = true;
        r.setFaults(Axis::Elevation, freeze);
        r.pointElevation(30.0);
        r.advanceBy(3.0);
        QCOMPARE(elByte(r), 8);
        QCOMPARE(r.errorRegister(), 2);
        QCOMPARE(r.readInput(4).value(), 0.0);

        SimulatedRotator n;
        AxisFaults noise;
        noise.encoderNoise = 0.5;
        n.setFaults(Axis::Azimuth, noise);
        n.advanceBy(0.1);
        QCOMPARE(n.errorRegister(), 2);
        QCOMPARE(azByte(n), 8);
    }

    void missingEndStopShowsAsAHomingError()
    {
        SimulatedRotator r(withAzimuthRange(360.0, 30.0));
        AxisFaults f;
        f.missingEndStop = true;
        r.setFaults(Axis::Azimuth, f);
        r.reset();
        r.advanceBy(15.0);
        QCOMPARE(r.errorRegister(), 4);
        QCOMPARE(azByte(r), 8);
        QCOMPARE(r.readInput(1).value(), 0.0); // the switch never tripped
        QVERIFY(r.axis(Axis::Azimuth).antennaPosition() >= -1.0);
        QCOMPARE(elByte(r), 4); // elevation homed fine
    }

    void defaultIsAG5500ClassRotator()
    {
        SimulatedRotator r;
        QCOMPARE(r.axis(Axis::Azimuth).plant().maxSpeed, 6.2);
        QCOMPARE(r.axis(Axis::Elevation).plant().maxSpeed, 2.7);
        QCOMPARE(r.axis(Axis::Azimuth).plant().driveTrain, DriveTrain::SelfLocking);
        r.driveAzimuth(30000.0); // asks for more than the motor can do
        r.driveElevation(30000.0);
        r.advanceBy(3.0);
        QVERIFY(std::fabs(r.axis(Axis::Azimuth).velocity() - 6.2) < 0.01);
        QVERIFY(std::fabs(r.axis(Axis::Elevation).velocity() - 2.7) < 0.01);
        // At the speed cap the motor only works against friction: a long
        // slew is not a long stall.
        QVERIFY2(r.readInput(5).value() < 15.0, qPrintable(QString::number(r.readInput(5).value())));
        QVERIFY(r.readInput(5).value() > 0.0);
    }

    void stopFromFullSpeedHoldsWithinADegree_data()
    {
        QTest::addColumn<QString>("model");
        for (const RotatorModel &m : rotatorModels())
            QTest::newRow(m.name) << QString::fromLatin1(m.name);
    }

    void stopFromFullSpeedHoldsWithinADegree()
    {
        QFETCH(QString, model);
        RotatorConfig c = withAzimuthRange(450.0, 10.0);
        applyRotatorModel(c, *findRotatorModel(model));
        SimulatedRotator r(c);
        r.pointAzimuth(440.0);
        r.pointElevation(170.0);
        r.advanceBy(6.0); // both axes at full speed
        const double az = r.axis(Axis::Azimuth).antennaPosition();
        const double el = r.axis(Axis::Elevation).antennaPosition();
        r.stopAzimuth();
        r.stopElevation();
        r.advanceBy(0.5);
        QCOMPARE(r.axis(Axis::Azimuth).velocity(), 0.0);
        QCOMPARE(r.axis(Axis::Elevation).velocity(), 0.0);
        QVERIFY(r.axis(Axis::Azimuth).antennaPosition() - az < 1.0);
        QVERIFY(r.axis(Axis::Elevation).antennaPosition() - el < 1.0);
        QCOMPARE(r.status(), 1 | (1 << 8)); // idle: the drive is released
    }

    void zeroSpeedBrakesAFreeDriveAndReportsIdleAtRest()
    {
        RotatorConfig c = withAzimuthRange(450.0, 10.0);
        c.azimuth.driveTrain = c.elevation.driveTrain = DriveTrain::FreeRunning;
        SimulatedRotator r(c);
        r.driveAzimuth(30000.0);
        r.advanceBy(3.0);
        QCOMPARE(azByte(r), 2);
        r.stopAzimuth();
        r.advanceBy(0.25);
        QVERIFY(r.axis(Axis::Azimuth).velocity() > 20.0); // a free drive coasts
        r.driveAzimuth(0.0);
        r.advanceBy(1.75);
        QVERIFY(std::fabs(r.axis(Axis::Azimuth).velocity()) < 0.01); // braked by the speed loop
        QCOMPARE(azByte(r), 1);
    }

    void encodersReportTicks()
    {
        RotatorConfig c;
        c.azimuth.ticksPerDegree = 1000.0;
        c.startAzimuth = 12.5;
        SimulatedRotator r(c);
        const auto e = r.encoders();
        QCOMPARE(e[0], 12500);
        QCOMPARE(e[1], 0);
        r.driveAzimuth(2000.0);
        r.advanceBy(3.0);
        QVERIFY(std::llabs(r.encoders()[2] - 2000) < 30);
    }
};

QTEST_GUILESS_MAIN(TestSimulatedRotator)
#include "tst_simulatedrotator.moc"
