// SPDX-License-Identifier: GPL-3.0-or-later
// The firmware alone: bytes in, bytes out, per dialect. Time is stepped on
// the rotator directly, so nothing here waits.
#include "sim/rotatormodels.h"
#include "sim/simulatedrotator.h"
#include "sim/simulatorfirmware.h"

#include <QRandomGenerator>
#include <QTest>

#include <cmath>

using namespace slew::sim;
using slew::protocol::Dialect;

class TestSimulatorFirmware : public QObject {
    Q_OBJECT

    // The fast SatNOGS-class rotator: these cases are about bytes, and its
    // speed lets them reach a position in a few simulated seconds.
    static RotatorConfig fastConfig()
    {
        RotatorConfig c;
        applyRotatorModel(c, *findRotatorModel(u"satnogs"));
        return c;
    }

    struct Bench {
        explicit Bench(Dialect d, RotatorConfig config = fastConfig()) : rotator(config), firmware(rotator, counters, d) {}
        SimulatedRotator rotator;
        FirmwareCounters counters;
        SimulatorFirmware firmware;
        QByteArray send(QByteArrayView bytes) { return firmware.receive(bytes); }
    };

private slots:
    void hamlib45QueryIsAnsweredOnOneLine_data()
    {
        QTest::addColumn<int>("dialect");
        QTest::addColumn<QByteArray>("expected");
        QTest::newRow("easycomm2") << int(Dialect::Easycomm2) << QByteArray("AZ0.0 EL0.0\n");
        QTest::newRow("satnogs") << int(Dialect::SatNogs) << QByteArray("AZ0.0 EL0.0\n");
        QTest::newRow("easycomm3") << int(Dialect::Easycomm3) << QByteArray("AZ0.00 EL0.00\n");
    }
    void hamlib45QueryIsAnsweredOnOneLine()
    {
        QFETCH(int, dialect);
        QFETCH(QByteArray, expected);
        Bench b{Dialect(dialect)};
        QCOMPARE(b.send("AZ EL \n"), expected);
    }

    void hamlib46QueriesAreAnsweredSeparately()
    {
        Bench b(Dialect::Easycomm2);
        b.rotator.pointAzimuth(10.0);
        b.rotator.pointElevation(20.0);
        b.rotator.advanceBy(10.0);
        QCOMPARE(b.send("AZ\n"), QByteArray("AZ10.0\n"));
        QCOMPARE(b.send("EL\n"), QByteArray("EL20.0\n"));
        // Split anywhere, the answer is the same.
        QCOMPARE(b.send("A"), QByteArray());
        QCOMPARE(b.send("Z E"), QByteArray());
        QCOMPARE(b.send("L\r\n"), QByteArray("AZ10.0 EL20.0\n"));
    }

    void satnogsConfigReadHasNoPrefixAndStraySemicolonsAreHarmless()
    {
        Bench b(Dialect::SatNogs);
        QCOMPARE(b.send("CR 1\n;"), QByteArray("1,40.000\n"));
        QCOMPARE(b.send("CR 7\n;"), QByteArray("7,0.00\n"));
        QCOMPARE(b.send("GS\n;"), QByteArray("GS1\n"));
        QCOMPARE(b.send("GE\n;"), QByteArray("GE1\n"));
        QVERIFY(b.send("VE\n;").startsWith("VESatNOGS-v2.2"));
        QCOMPARE(b.send("CW1,35\n;"), QByteArray());
        QCOMPARE(b.send("CR 1\n"), QByteArray("1,35.000\n"));
        QCOMPARE(b.counters.rejected(), 0u);
    }

    void satnogsFirmwareSaysPointingAndReadsOneDigit()
    {
        // As the SatNOGS firmware v2.2 answers (docs/protocol.md,
        // "Controllers in the field"): GS4 for the whole of a move, never
        // the moving bit; CR10 read as register 1.
        Bench b(Dialect::SatNogs);
        b.firmware.setFirmware(Firmware::SatNogs);
        QCOMPARE(b.send("GS\n"), QByteArray("GS1\n"));
        QCOMPARE(b.send("AZ90.0 EL30.0\n"), QByteArray());
        b.rotator.advanceBy(0.5);
        QCOMPARE(b.send("GS\n"), QByteArray("GS4\n"));
        QCOMPARE(b.send("CR 10\n"), QByteArray("1,40.000\n"));
        QCOMPARE(b.send("CR 11\n"), QByteArray("1,40.000\n"));
        QCOMPARE(b.send("CR 7\n"), QByteArray("7,0.00\n"));
        b.rotator.advanceBy(60.0);
        QCOMPARE(b.send("AZ EL\n"), QByteArray("AZ90.0 EL30.0\n"));
        QCOMPARE(b.send("GS\n"), QByteArray("GS4\n")); // holding the position it reached: the same word
        // Slew's own reading of the dialect has the moving bit and CR10.
        Bench own(Dialect::SatNogs);
        QCOMPARE(own.send("AZ90.0 EL30.0\n"), QByteArray());
        own.rotator.advanceBy(0.5);
        QCOMPARE(own.send("GS\n"), QByteArray("GS2\n"));
        QCOMPARE(own.send("CR 10\n"), QByteArray("10,90.00\n"));
    }

    void satnogsFirmwareStopsByHoldingWhereItWas()
    {
        // SA SE makes where the axis is its set point: still turning, it runs
        // past and is driven back there. Slew's own reading lets go instead.
        Bench b(Dialect::SatNogs);
        b.firmware.setFirmware(Firmware::SatNogs);
        QCOMPARE(b.send("AZ300.0 EL0.0\n"), QByteArray());
        b.rotator.advanceBy(3.0);
        const double stoppedAt = b.rotator.axis(Axis::Azimuth).position();
        QVERIFY2(std::abs(b.rotator.axis(Axis::Azimuth).velocity()) > 1.0, "not turning when stopped");
        b.send("SA SE\n");
        double farthest = stoppedAt;
        for (int i = 0; i < 2000; ++i) {
            b.rotator.advanceBy(0.005);
            farthest = std::max(farthest, b.rotator.axis(Axis::Azimuth).position());
        }
        const double after = b.rotator.axis(Axis::Azimuth).position();
        qInfo("SatNOGS: stopped at %.2f, ran on to %.2f, back at %.2f", stoppedAt, farthest, after);
        QVERIFY2(farthest > stoppedAt + 0.1, qPrintable(QString::number(farthest - stoppedAt)));
        QVERIFY2(std::abs(after - stoppedAt) < 0.1, qPrintable(QString::number(after - stoppedAt)));

        Bench own(Dialect::SatNogs);
        QCOMPARE(own.send("AZ300.0 EL0.0\n"), QByteArray());
        own.rotator.advanceBy(3.0);
        const double ownStop = own.rotator.axis(Axis::Azimuth).position();
        own.send("SA SE\n");
        own.rotator.advanceBy(10.0);
        const double ownAfter = own.rotator.axis(Axis::Azimuth).position();
        qInfo("as documented: stopped at %.2f, at rest at %.2f", ownStop, ownAfter);
        QVERIFY(ownAfter >= ownStop);
    }

    void k3ngStopsWithinItsAzimuthTolerance()
    {
        Bench b(Dialect::Gs232B);
        b.firmware.setFirmware(Firmware::K3ng);
        b.rotator.pointAzimuth(59.0);
        b.rotator.pointElevation(25.0);
        b.rotator.advanceBy(30.0);
        QCOMPARE(b.send("C2\r"), QByteArray("AZ=059EL=025\r\n"));
        // Within its 3°: the relay is not even closed.
        QCOMPARE(b.send("W061 025\r"), QByteArray());
        b.rotator.advanceBy(10.0);
        QCOMPARE(b.send("C2\r"), QByteArray("AZ=059EL=025\r\n"));
        // Farther: it lets go 2.3° short, inside its tolerance.
        QCOMPARE(b.send("W094 025\r"), QByteArray());
        b.rotator.advanceBy(30.0);
        const double az = b.rotator.axis(Axis::Azimuth).position();
        QVERIFY2(std::abs(az - 91.7) < 0.2, qPrintable(QString::number(az)));
    }

    void easycomm3AnswersWithTwoDecimalsAndPrefixes()
    {
        Bench b(Dialect::Easycomm3);
        b.rotator.pointAzimuth(123.45);
        b.rotator.advanceBy(15.0);
        QCOMPARE(b.send("AZ\n"), QByteArray("AZ123.45\n"));
        QCOMPARE(b.send("CR10\n"), QByteArray("CR10,123.45\n"));
        QCOMPARE(b.send("IP3\n"), QByteArray("IP3,123.45\n"));
        QCOMPARE(b.send("IP1\n"), QByteArray("IP1,0\n"));
        QCOMPARE(b.send("IP2\n"), QByteArray("IP2,1\n")); // elevation rests on its lower switch
        QCOMPARE(b.send("GS\n"), QByteArray("GS260\n")); // az pointing (4), el idle (1 << 8)
        QCOMPARE(b.send("\\?ENC\n"), QByteArray("\\?ENC12345,0,0,0\n"));
    }

    void velocityCommandsAreMillidegreesPerSecond()
    {
        Bench b(Dialect::Easycomm3);
        b.rotator.pointAzimuth(100.0);
        b.rotator.advanceBy(10.0);
        QCOMPARE(b.send("VR4900\n"), QByteArray());
        b.rotator.advanceBy(3.0);
        const QByteArray speed = b.send("IP7\n");
        QVERIFY(speed.startsWith("IP7,"));
        QVERIFY2(qAbs(speed.mid(4).trimmed().toDouble() - 4.9) < 0.05, speed.constData());
        QCOMPARE(b.send("CR12\n"), QByteArray("CR12,4900.00\n"));
        QCOMPARE(b.send("VR\n"), QByteArray("VR4900\n"));
        QCOMPARE(b.send("GS\n"), QByteArray("GS258\n")); // az velocity servo (2), el idle
        QCOMPARE(b.send("VL2000\n"), QByteArray());
        QCOMPARE(b.send("CR12\n"), QByteArray("CR12,-2000.00\n"));
        QCOMPARE(b.send("VL\n"), QByteArray("VL2000\n"));
    }

    void gs232RelativeMoveIsFromThePresentPosition()
    {
        // The easycom library's O+aaa-eee: offsets from where the axes are.
        Bench b(Dialect::Gs232B);
        b.rotator.pointAzimuth(100.0);
        b.rotator.pointElevation(20.0);
        b.rotator.advanceBy(15.0);
        QCOMPARE(b.send("O+030-005\r"), QByteArray());
        b.rotator.advanceBy(15.0);
        QCOMPARE(b.send("C2\r"), QByteArray("AZ=130  EL=015\r\n"));
        // Past a limit: the Yaesu prompt, and nothing moves.
        QCOMPARE(b.send("O+000-030\r"), QByteArray("?>\r\n"));
        QCOMPARE(b.counters.outOfLimits, std::uint64_t(1));
        b.rotator.advanceBy(5.0);
        QCOMPARE(b.send("C2\r"), QByteArray("AZ=130  EL=015\r\n"));
    }

    void gs232StatusIsAnsweredAsST()
    {
        // GS (the easycom library's table) -> ST=n, the bits of SatNOGS' GS.
        Bench b(Dialect::Gs232A);
        QCOMPARE(b.send("GS\r"), QByteArray("ST=1\r\n")); // idle
        b.rotator.pointAzimuth(90.0);
        b.rotator.advanceBy(0.5);
        const QByteArray moving = b.send("GS\r");
        QVERIFY2(moving.startsWith("ST=") && (moving.mid(3).trimmed().toInt() & 2), moving.constData());
        // A status sent to the controller is not a command.
        QCOMPARE(b.send("ST=1\r"), QByteArray("?>\r\n"));
    }

    void refusedInputMovesNothingIsCountedAndRaisesAnAlarm_data()
    {
        QTest::addColumn<QByteArray>("input");
        QTest::addColumn<QByteArray>("alarm");
        QTest::newRow("unknown") << QByteArray("XY12\n") << QByteArray("ALunknown:XY12\n");
        QTest::newRow("malformed") << QByteArray("AZ12x\n") << QByteArray("ALmalformed:AZ12x\n");
        QTest::newRow("over the limit") << QByteArray("AZ500\n") << QByteArray("ALlimit:AZ500.00\n");
        QTest::newRow("negative") << QByteArray("EL-5\n") << QByteArray("ALlimit:EL-5.00\n");
        // The alarm shows the value refused, not a rounding that would pass.
        QTest::newRow("just below zero") << QByteArray("AZ-0.004\n") << QByteArray("ALlimit:AZ-0.004\n");
        QTest::newRow("elevation just below zero") << QByteArray("EL-0.001\n") << QByteArray("ALlimit:EL-0.001\n");
        QTest::newRow("velocity too large") << QByteArray("VL99999999999999999999\n")
                                            << QByteArray("ALmalformed:VL99999999999999999999\n");
        QTest::newRow("velocity past 32 bits") << QByteArray("VL2147483648\n") << QByteArray("ALmalformed:VL2147483648\n");
        QTest::newRow("velocity one over") << QByteArray("VR100000\n") << QByteArray("ALmalformed:VR100000\n");
        QTest::newRow("time out of range") << QByteArray("ST99:99:99:99:99:99\n")
                                           << QByteArray("ALmalformed:ST99:99:99:99:99:99\n");
        QTest::newRow("no such register") << QByteArray("CW44,1\n") << QByteArray("ALlimit:CW44,1\n");
        QTest::newRow("overlong") << QByteArray(300, 'A') + '\n' << QByteArray("ALoverlong:") + QByteArray(32, 'A') + '\n';
    }
    void refusedInputMovesNothingIsCountedAndRaisesAnAlarm()
    {
        QFETCH(QByteArray, input);
        QFETCH(QByteArray, alarm);
        Bench b(Dialect::Easycomm3);
        QCOMPARE(b.send(input), alarm);
        QCOMPARE(b.counters.rejected(), 1u);
        b.rotator.advanceBy(2.0);
        QCOMPARE(b.rotator.axis(Axis::Azimuth).position(), 0.0);
        QCOMPARE(b.rotator.axis(Axis::Elevation).position(), 0.0);
        QCOMPARE(b.rotator.axis(Axis::Azimuth).mode(), DriveMode::Released);
        // Nothing commanded: the registers still read the start.
        QCOMPARE(b.send("CR10 CR12\n"), QByteArray("CR10,0.00 CR12,0.00\n"));
    }

    void refusedTimeKeepsTheClock()
    {
        Bench b(Dialect::Easycomm2);
        QCOMPARE(b.send("ST26:11:21:23:00:00\n"), QByteArray());
        QCOMPARE(b.send("ST99:99:99:99:99:99\n"), QByteArray("ALmalformed:ST99:99:99:99:99:99\n"));
        QCOMPARE(b.send("ST\n"), QByteArray("ST26:11:21:23:00:00\n"));
    }

    void satnogsRefusesSilently()
    {
        Bench b(Dialect::SatNogs);
        QCOMPARE(b.send("AZ500 FOO\n"), QByteArray());
        QCOMPARE(b.counters.outOfLimits, std::uint64_t(1));
        QCOMPARE(b.counters.unknown, 1u);
    }

    void easycomm1LineMovesWithoutAnswering()
    {
        Bench b(Dialect::Easycomm1);
        QCOMPARE(b.send("AZ10.0 EL20.0 UP000 XXX DN000 XXX\n"), QByteArray());
        QCOMPARE(b.rotator.readRegister(10).value(), 10.0);
        QCOMPARE(b.rotator.readRegister(11).value(), 20.0);
        QCOMPARE(b.counters.rejected(), 0u);
    }

    void spaceTerminatedCommandWaitsForTheLineEnd()
    {
        Bench b(Dialect::Easycomm3);
        QCOMPARE(b.send("GS "), QByteArray());
        QVERIFY(b.firmware.awaitingLineEnd());
        QCOMPARE(b.firmware.endLine(), QByteArray("GS257\n"));
    }

    void unsolicitedPushesOnlyWhatChanged()
    {
        Bench b(Dialect::Easycomm3);
        const QByteArray first = b.firmware.unsolicitedChanges();
        QVERIFY(first.startsWith("AZ0.00\nEL0.00\nIP0,25.00\n"));
        QVERIFY(first.contains("\nGS257\nGE1\nVESlewSim-1.0\n"));
        QCOMPARE(b.firmware.unsolicitedChanges(), QByteArray());
        b.send("AZ5\n");
        b.rotator.advanceBy(0.5);
        const QByteArray moving = b.firmware.unsolicitedChanges();
        QVERIFY(moving.startsWith("AZ"));
        QVERIFY(moving.contains("CR10,5.00\n"));
        QVERIFY(moving.contains("GS262\n"));
        QVERIFY(!moving.contains("EL"));
        QVERIFY(!moving.contains("VE"));
    }

    void alarmFloodIsSummarised()
    {
        Bench b(Dialect::Easycomm3);
        QByteArray input;
        for (int i = 0; i < 20; ++i)
            input += "QQ ";
        const QByteArray out = b.send(input + "GE\n");
        QCOMPARE(out.count("ALunknown:QQ\n"), 8);
        QVERIFY2(out.endsWith("GE1\nALsuppressed:12\n"), out.constData());
        QCOMPARE(b.counters.unknown, 20u);
    }

    void garbageBarrageNeverBreaksAValidQuery()
    {
        Bench b(Dialect::Easycomm3);
        QRandomGenerator rng(42);
        for (int round = 0; round < 200; ++round) {
            QByteArray junk(int(rng.bounded(1, 4096)), '\0');
            for (char &c : junk)
                c = char(rng.bounded(256));
            b.send(junk);
        }
        QVERIFY(b.counters.rejected() > 100u);
        b.send("\n");
        QCOMPARE(b.send("GE\n"), QByteArray("GE1\n"));
        QCOMPARE(b.send("AZ EL\n").left(2), QByteArray("AZ"));
    }
};

QTEST_GUILESS_MAIN(TestSimulatorFirmware)
#include "tst_simulatorfirmware.moc"
