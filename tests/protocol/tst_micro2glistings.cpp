// SPDX-License-Identifier: GPL-3.0-or-later
// The Micro-2g `Z` and `V` listings read into numbers
// (protocol/micro2glistings.h): the forms docs/protocol.md gives, what a
// tolerant reader accepts, and what it must refuse.
#include "protocol/micro2glistings.h"
#include "protocol/parser.h"

#include <QTest>

using namespace slew::protocol;

class Micro2gListingsTest : public QObject {
    Q_OBJECT
private slots:
    void readsACalibrationLine_data()
    {
        QTest::addColumn<QByteArray>("line");
        QTest::addColumn<int>("rotor");
        QTest::addColumn<int>("leftAdc");
        QTest::addColumn<int>("leftBearing");
        QTest::addColumn<int>("rightAdc");
        QTest::addColumn<int>("rightBearing");
        QTest::addColumn<int>("range");
        QTest::newRow("north stop") << QByteArray("Z1L 3990=000 Z1R 2440=090 Z1D 450")
                                    << 1 << 3990 << 0 << 2440 << 90 << 450;
        QTest::newRow("south stop") << QByteArray("Z2L 3990=180 Z2R 2440=270 Z2D 450")
                                    << 2 << 3990 << 180 << 2440 << 270 << 450;
        QTest::newRow("lower case, blanks") << QByteArray("  z4l 12=5\tz4r  4095=359 z4d 90 ")
                                            << 4 << 12 << 5 << 4095 << 359 << 90;
    }
    void readsACalibrationLine()
    {
        QFETCH(QByteArray, line);
        const std::optional<Micro2gCalibration> c = readMicro2gCalibration(line);
        QVERIFY(c);
        QFETCH(int, rotor);
        QFETCH(int, leftAdc);
        QFETCH(int, leftBearing);
        QFETCH(int, rightAdc);
        QFETCH(int, rightBearing);
        QFETCH(int, range);
        QCOMPARE(*c, (Micro2gCalibration{rotor, leftAdc, leftBearing, rightAdc, rightBearing, range}));
    }

    void refusesWhatIsNotACalibrationLine_data()
    {
        QTest::addColumn<QByteArray>("line");
        QTest::newRow("a command") << QByteArray("Z1L 000");
        QTest::newRow("groups of two rotors") << QByteArray("Z1L 3990=000 Z2R 2440=090 Z1D 450");
        QTest::newRow("groups out of order") << QByteArray("Z1R 2440=090 Z1L 3990=000 Z1D 450");
        QTest::newRow("rotor 5") << QByteArray("Z5L 3990=000 Z5R 2440=090 Z5D 450");
        QTest::newRow("reading over 12 bits") << QByteArray("Z1L 4096=000 Z1R 2440=090 Z1D 450");
        QTest::newRow("bearing 360") << QByteArray("Z1L 3990=360 Z1R 2440=090 Z1D 450");
        QTest::newRow("no bearing") << QByteArray("Z1L 3990 Z1R 2440=090 Z1D 450");
        QTest::newRow("range not a number") << QByteArray("Z1L 3990=000 Z1R 2440=090 Z1D 4x0");
        QTest::newRow("a word too many") << QByteArray("Z1L 3990=000 Z1R 2440=090 Z1D 450 Z1D 450");
        QTest::newRow("empty") << QByteArray();
    }
    void refusesWhatIsNotACalibrationLine()
    {
        QFETCH(QByteArray, line);
        QVERIFY(!readMicro2gCalibration(line));
    }

    void readsAdcReadings()
    {
        const QList<Micro2gAdcReading> r = readMicro2gAdcReadings("V1=3990 V2=2440,v3=0  V4=4095");
        QCOMPARE(r.size(), 4);
        QCOMPARE(r[0].rotor, 1);
        QCOMPARE(r[0].counts, 3990);
        QCOMPARE(r[1].counts, 2440);
        QCOMPARE(r[2].rotor, 3);
        QCOMPARE(r[2].counts, 0);
        QCOMPARE(r[3].counts, 4095);
        QVERIFY(readMicro2gAdcReadings("V1=4096").isEmpty());
        QVERIFY(readMicro2gAdcReadings("V1=3990 T2=20").isEmpty());
        QVERIFY(readMicro2gAdcReadings("V5=1").isEmpty());
        QVERIFY(readMicro2gAdcReadings("").isEmpty());
    }

    // What the parser hands on is what these read: a `Z` answer's text is
    // the line, a `V` answer's Slew's form of it.
    void readsWhatTheParserHandsOn()
    {
        Parser parser(Dialect::Micro2g);
        QList<Message> got;
        parser.feed("z3l 3000=045  z3r 1000=135 z3d 540\rv1=3990, v2=17\r", [&](const Message &m) { got.append(m); });
        QCOMPARE(got.size(), 2);
        QCOMPARE(got[0].op, Op::Calibration);
        QCOMPARE(got[0].index, 3);
        QCOMPARE(*readMicro2gCalibration(got[0].text.view()), (Micro2gCalibration{3, 3000, 45, 1000, 135, 540}));
        QCOMPARE(got[1].op, Op::AdcReadings);
        const QList<Micro2gAdcReading> r = readMicro2gAdcReadings(got[1].text.view());
        QCOMPARE(r.size(), 2);
        QCOMPARE(r[1].rotor, 2);
        QCOMPARE(r[1].counts, 17);
    }
};

QTEST_APPLESS_MAIN(Micro2gListingsTest)
#include "tst_micro2glistings.moc"
