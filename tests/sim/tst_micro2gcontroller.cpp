// SPDX-License-Identifier: GPL-3.0-or-later
// The Micro-2g controller program, simulated: every command of its
// document, the north- and south-stop calibrations it gives as examples,
// the short way through the 450-degree overlap, and refusals that change
// nothing.

#include "sim/micro2g/micro2gcontroller.h"

#include <QTest>

using slew::sim::Micro2gController;
using Drive = Micro2gController::Drive;

namespace {

// A tolerance of 20 counts on a 1550-count, 450-degree potentiometer.
constexpr double kDefaultToleranceDegrees = 20.0 * 450.0 / 1550.0;

// Runs until every rotor's relays have dropped, at most `limit` seconds.
double settle(Micro2gController &c, double limit = 200)
{
    double t = 0;
    auto moving = [&] {
        for (int n = 1; n <= Micro2gController::kRotors; ++n) {
            if (c.drive(n) != Drive::Off)
                return true;
        }
        return false;
    };
    c.advance(0.01);
    while (moving() && t < limit) {
        c.advance(0.1);
        t += 0.1;
    }
    return t;
}

double angleBetween(double a, double b)
{
    const double d = std::fmod(std::abs(a - b), 360.0);
    return std::min(d, 360.0 - d);
}

} // namespace

class Micro2gControllerTest : public QObject {
    Q_OBJECT
private slots:
    void printsItsState();
    void turnsToAHeadingAndStopsWithinTolerance();
    void takesTheShortWayThroughTheOverlap();
    void presetsGoAndLoad();
    void selectsAndAddressesEachRotor();
    void stopsARotorWhereItIs();
    void toleranceIsPerRotor();
    void northStopExampleReadsTrueBearings();
    void southStopExampleReadsTrueBearings();
    void calibratesFromWhereTheRotorStands();
    void loggingProgramPrefixIsAccepted();
    void refusalsChangeNothing_data();
    void refusalsChangeNothing();
    void aBackwardsCalibrationStallsAndGivesUp();
    void settingsSurviveARestartOnlyWhenKept();
};

void Micro2gControllerTest::printsItsState()
{
    Micro2gController c;
    QCOMPARE(c.handle("C"), QStringList{"+0000"});
    QCOMPARE(c.handle("V"), QStringList{"V1=3990 V2=3990 V3=3990 V4=3990"});
    QCOMPARE(c.handle("T"), QStringList{"T1=20 T2=20 T3=20 T4=20"});
    QCOMPARE(c.handle("R"), QStringList{"R1=- R2=- R3=- R4=-"});
    const QStringList z = c.handle("Z");
    QCOMPARE(z.size(), 4);
    QCOMPARE(z[0], QString("Z1L 3990=000 Z1R 2440=090 Z1D 450"));
    QCOMPARE(z[3], QString("Z4L 3990=000 Z4R 2440=090 Z4D 450"));
    QVERIFY(c.handle("?").first().contains("4 rotors, default rotor 1"));
    QCOMPARE(c.handle(""), QStringList{});
    QCOMPARE(c.handle("c"), QStringList{"+0000"}); // a terminal may send lower case
}

void Micro2gControllerTest::turnsToAHeadingAndStopsWithinTolerance()
{
    Micro2gController c;
    QCOMPARE(c.handle("M035"), QStringList{});
    c.advance(0.5);
    QCOMPARE(c.drive(1), Drive::Right);
    QCOMPARE(c.handle("R"), QStringList{"R1=R R2=- R3=- R4=-"});
    const double seconds = settle(c);
    QVERIFY2(seconds < 10, qPrintable(QString::number(seconds)));
    // The relays drop as the reading enters the tolerance band.
    QVERIFY(std::abs(c.heading(1) - 35) <= kDefaultToleranceDegrees + 0.5);
    QVERIFY(std::abs(c.trueBearing(1) - c.heading(1)) < 0.5);
    QCOMPARE(c.handle("C"), QStringList{QStringLiteral("+0%1").arg(int(std::lround(c.heading(1))), 3, 10, QChar('0'))});
}

void Micro2gControllerTest::takesTheShortWayThroughTheOverlap()
{
    Micro2gController c;
    // To 400 degrees of travel (bearing 040, in the overlap).
    c.handle("T1 2");
    c.handle("M180");
    settle(c);
    c.handle("M300");
    settle(c);
    c.handle("M040"); // 40 is at travel 40 and 400; from 300 the near one is 400
    settle(c);
    QVERIFY2(std::abs(c.travel(1) - 400) < 1.0, qPrintable(QString::number(c.travel(1))));
    c.handle("M030"); // 390, not the long way back to 30
    c.advance(0.2);
    QCOMPARE(c.drive(1), Drive::Left);
    settle(c);
    QVERIFY2(std::abs(c.travel(1) - 390) < 1.0, qPrintable(QString::number(c.travel(1))));
    // From 390, 000 is nearer at travel 360 than at 0.
    c.handle("M000");
    settle(c);
    QVERIFY2(std::abs(c.travel(1) - 360) < 1.0, qPrintable(QString::number(c.travel(1))));
    // From the low end, 050 is reached at 50, not at 410.
    c.handle("M100");
    settle(c);
    c.handle("M000");
    settle(c);
    QVERIFY2(std::abs(c.travel(1)) < 1.0, qPrintable(QString::number(c.travel(1))));
    c.handle("M050");
    settle(c);
    QVERIFY2(std::abs(c.travel(1) - 50) < 1.0, qPrintable(QString::number(c.travel(1))));
}

void Micro2gControllerTest::presetsGoAndLoad()
{
    Micro2gController c;
    c.handle("T1 2");
    c.handle("P2"); // default rotor, preset 2 = 90
    settle(c);
    QVERIFY(angleBetween(c.heading(1), 90) < 1.0);
    c.handle("P13"); // rotor 1, preset 3 = 180
    settle(c);
    QVERIFY(angleBetween(c.heading(1), 180) < 1.0);
    c.handle("P1");
    settle(c);
    QVERIFY(angleBetween(c.heading(1), 45) < 1.0);

    // L: store where rotor 2 stands now as its preset 1, then go back to it.
    c.handle("T2 2");
    c.handle("2");
    c.handle("M123");
    settle(c);
    QCOMPARE(c.handle("L21"), QStringList{});
    c.handle("M010");
    settle(c);
    c.handle("P21");
    settle(c);
    QVERIFY(angleBetween(c.heading(2), 123) < 1.0);
    QVERIFY(angleBetween(c.heading(1), 45) < 1.0); // rotor 1 untouched
    c.handle("L3"); // default rotor (2) preset 3
    c.handle("M200");
    settle(c);
    c.handle("P3");
    settle(c);
    QVERIFY(angleBetween(c.heading(2), 123) < 1.0);
}

void Micro2gControllerTest::selectsAndAddressesEachRotor()
{
    Micro2gController c;
    for (int n = 1; n <= 4; ++n) {
        QCOMPARE(c.handle(QString::number(n)), QStringList{});
        QCOMPARE(c.defaultRotor(), n);
        c.handle(QStringLiteral("M%1").arg(20 * n, 3, 10, QChar('0')));
    }
    settle(c);
    for (int n = 1; n <= 4; ++n) {
        QVERIFY2(std::abs(c.heading(n) - 20 * n) <= kDefaultToleranceDegrees + 0.5, qPrintable(QString::number(n)));
        QCOMPARE(c.handle(QStringLiteral("C%1").arg(n)),
                 QStringList{QStringLiteral("+0%1").arg(int(std::lround(c.heading(n))), 3, 10, QChar('0'))});
    }
    QCOMPARE(c.handle("C"), c.handle("C4"));
}

void Micro2gControllerTest::stopsARotorWhereItIs()
{
    Micro2gController c;
    c.handle("M180");
    c.handle("3");
    c.handle("M180");
    c.advance(3.0);
    QCOMPARE(c.handle("S1"), QStringList{});
    c.advance(0.01);
    QCOMPARE(c.drive(1), Drive::Off);
    QCOMPARE(c.drive(3), Drive::Right);
    const double stoppedAt = c.travel(1);
    c.advance(5.0);
    QCOMPARE(c.travel(1), stoppedAt); // a worm gear holds
    QCOMPARE(c.handle("S"), QStringList{}); // the default rotor, 3
    c.advance(0.01);
    QCOMPARE(c.drive(3), Drive::Off);
}

void Micro2gControllerTest::toleranceIsPerRotor()
{
    Micro2gController c;
    QCOMPARE(c.handle("T2 3"), QStringList{});
    QCOMPARE(c.handle("T"), QStringList{"T1=20 T2=3 T3=20 T4=20"});
    c.handle("M100");
    c.handle("2");
    c.handle("M100");
    settle(c);
    QVERIFY(std::abs(c.heading(2) - 100) <= 3 * 450.0 / 1550.0 + 0.5);
    QVERIFY(std::abs(c.heading(2) - 100) < std::abs(c.heading(1) - 100));
}

void Micro2gControllerTest::northStopExampleReadsTrueBearings()
{
    // The document's north-stop setup is the default.
    Micro2gController c;
    for (const char *line : {"Z1L 3990=000", "Z1R 2440=090", "Z1D 450"})
        QCOMPARE(c.handle(line), QStringList{});
    c.handle("T1 2");
    for (int bearing : {0, 45, 90, 180, 270, 359}) {
        c.handle(QStringLiteral("M%1").arg(bearing, 3, 10, QChar('0')));
        settle(c);
        QVERIFY2(angleBetween(c.heading(1), bearing) < 1.0, qPrintable(QString::number(bearing)));
        QVERIFY2(angleBetween(c.trueBearing(1), c.heading(1)) < 0.5, qPrintable(QString::number(bearing)));
    }
}

void Micro2gControllerTest::southStopExampleReadsTrueBearings()
{
    // The same rotor mounted with its left stop pointing south.
    std::array<Micro2gController::Mechanics, 4> mechanics{};
    mechanics[0].leftStopBearing = 180;
    Micro2gController c(mechanics);
    // With the north-stop calibration it reads 180 degrees off.
    QVERIFY(angleBetween(c.heading(1), c.trueBearing(1)) > 179);
    for (const char *line : {"Z1L 3990=180", "Z1R 2440=270", "Z1D 450"})
        QCOMPARE(c.handle(line), QStringList{});
    QVERIFY(angleBetween(c.heading(1), c.trueBearing(1)) < 0.5);
    QCOMPARE(c.handle("C"), QStringList{"+0180"});
    c.handle("T1 2");
    for (int bearing : {180, 270, 0, 90, 200}) {
        c.handle(QStringLiteral("M%1").arg(bearing, 3, 10, QChar('0')));
        settle(c);
        QVERIFY2(angleBetween(c.trueBearing(1), bearing) < 1.0, qPrintable(QString::number(bearing)));
    }
    // 200 is at travel 20 and 380: from 90 (travel 270) the near one is 380.
    QVERIFY2(std::abs(c.travel(1) - 380) < 1.0, qPrintable(QString::number(c.travel(1))));
}

void Micro2gControllerTest::calibratesFromWhereTheRotorStands()
{
    // A rotor whose potentiometer reads differently from the defaults.
    std::array<Micro2gController::Mechanics, 4> mechanics{};
    mechanics[1].adcAtLeftStop = 3700;
    mechanics[1].adcAtRightStop = 600;
    Micro2gController c(mechanics);
    c.handle("2");
    // At the left stop (where it starts): this reading is bearing 0.
    QCOMPARE(c.handle("Z2L 000"), QStringList{});
    QCOMPARE(c.calibration(2).leftAdc, 3700);
    // To reach the right stop, a rough guess for its reading (0) makes the
    // program drive right until the rotor stalls against the stop: that is
    // where the right calibration is taken.
    QCOMPARE(c.handle("Z2R 0000=090"), QStringList{});
    c.handle("M300");
    settle(c);
    c.handle("M090"); // 90 is at travel 90 and 450: from 300, 450
    settle(c);
    QCOMPARE(c.travel(2), 450.0);
    QCOMPARE(c.handle("Z2R 090"), QStringList{});
    QCOMPARE(c.handle("Z2D 450"), QStringList{});
    QCOMPARE(c.calibration(2).rightAdc, c.adc(2));
    QVERIFY(c.handle("Z")[1].startsWith("Z2L 3700=000 Z2R "));
    // Now the headings it reads are true wherever the rotor stands.
    c.handle("T2 2");
    for (int bearing : {0, 120, 300}) {
        c.handle(QStringLiteral("M%1").arg(bearing, 3, 10, QChar('0')));
        settle(c);
        QVERIFY2(angleBetween(c.trueBearing(2), c.heading(2)) < 2.0,
                 qPrintable(QStringLiteral("%1: true %2, read %3").arg(bearing).arg(c.trueBearing(2)).arg(c.heading(2))));
    }
}

void Micro2gControllerTest::loggingProgramPrefixIsAccepted()
{
    Micro2gController a, b, d;
    a.handle("M035");
    b.handle("X4rM035");
    d.handle("X4M035");
    settle(a);
    settle(b);
    settle(d);
    QCOMPARE(b.travel(1), a.travel(1));
    QCOMPARE(d.travel(1), a.travel(1));
    QVERIFY(a.travel(1) > 20);
}

void Micro2gControllerTest::refusalsChangeNothing_data()
{
    QTest::addColumn<QString>("line");
    QTest::addColumn<QString>("reason");
    QTest::newRow("rotor 5") << "5" << "rotors are 1 to 4";
    QTest::newRow("rotor 0") << "0" << "rotors are 1 to 4";
    QTest::newRow("bearing 400") << "M400" << "bearing of 0 to 360";
    QTest::newRow("bearing words") << "Mabc" << "bearing of 0 to 360";
    QTest::newRow("bearing empty") << "M" << "bearing of 0 to 360";
    QTest::newRow("preset 4") << "P4" << "preset m 1 to 3";
    QTest::newRow("preset rotor 5") << "P51" << "preset m 1 to 3";
    QTest::newRow("load preset 0") << "L10" << "preset m 1 to 3";
    QTest::newRow("C rotor 7") << "C7" << "C or Cn";
    QTest::newRow("S rotor 9") << "S9" << "S or Sn";
    QTest::newRow("tolerance 0") << "T1 0" << "tolerance x 1 to 500";
    QTest::newRow("tolerance huge") << "T1 9999" << "tolerance x 1 to 500";
    QTest::newRow("tolerance rotor 6") << "T6 20" << "rotor n 1 to 4";
    QTest::newRow("range 10") << "Z1D 10" << "degree range of 90 to 540";
    QTest::newRow("bearing 360") << "Z1L 360" << "bearing of 0 to 359";
    QTest::newRow("adc 5000") << "Z1L 5000=000" << "A/D value of 0 to 4095";
    QTest::newRow("stops too close") << "Z1R 3985=090" << "at least 10 counts apart";
    QTest::newRow("Z nonsense") << "Z9Q 1" << "ZnL mmm";
    QTest::newRow("unknown") << "QQ" << "unknown command 'QQ'";
    QTest::newRow("X4 then junk") << "X4rQ" << "X4 must be followed";
    QTest::newRow("V extra") << "V2" << "unknown command";
}

void Micro2gControllerTest::refusalsChangeNothing()
{
    QFETCH(QString, line);
    QFETCH(QString, reason);
    Micro2gController c;
    c.handle("M100");
    c.advance(1.0);
    const QJsonObject before = c.settings();
    const double travel = c.travel(1);
    const QStringList reply = c.handle(line);
    QCOMPARE(reply.size(), 1);
    QVERIFY2(reply.first().startsWith("?> ") && reply.first().contains(reason), qPrintable(reply.first()));
    QCOMPARE(c.settings(), before);
    QCOMPARE(c.travel(1), travel);
    QCOMPARE(c.defaultRotor(), 1);
    QCOMPARE(c.drive(1), Drive::Right); // the move under way goes on
}

void Micro2gControllerTest::aBackwardsCalibrationStallsAndGivesUp()
{
    Micro2gController c;
    // Left and right swapped (in steps: no step may put both on one
    // reading): the program drives into the left stop.
    QCOMPARE(c.handle("Z1L 1000=000"), QStringList{});
    QCOMPARE(c.handle("Z1R 3990=090"), QStringList{});
    QCOMPARE(c.handle("Z1L 2440=000"), QStringList{});
    c.handle("M045");
    c.advance(0.5);
    QCOMPARE(c.drive(1), Drive::Left);
    QCOMPARE(c.travel(1), 0.0);
    c.advance(3.0);
    QCOMPARE(c.drive(1), Drive::Off);
    QCOMPARE(c.travel(1), 0.0);
}

void Micro2gControllerTest::settingsSurviveARestartOnlyWhenKept()
{
    Micro2gController first;
    first.handle("Z1L 3990=180");
    first.handle("Z1R 2440=270");
    first.handle("T3 7");
    first.handle("4");
    first.handle("M222");
    settle(first);
    first.handle("L42");
    const QJsonObject kept = first.settings();

    Micro2gController restarted; // power off, on: the document's defaults
    QVERIFY(restarted.settings() != kept);
    QCOMPARE(restarted.restoreSettings(kept), QString());
    QCOMPARE(restarted.settings(), kept);
    QCOMPARE(restarted.tolerance(3), 7);
    QCOMPARE(restarted.defaultRotor(), 4);

    QJsonObject broken = kept;
    broken.insert("default_rotor", 9);
    Micro2gController other;
    const QJsonObject defaults = other.settings();
    QVERIFY(!other.restoreSettings(broken).isEmpty());
    QCOMPARE(other.settings(), defaults);
}

QTEST_GUILESS_MAIN(Micro2gControllerTest)
#include "tst_micro2gcontroller.moc"
