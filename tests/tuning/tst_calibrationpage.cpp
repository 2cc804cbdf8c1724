// SPDX-License-Identifier: GPL-3.0-or-later
// The setup wizard's calibration page on the simulated Micro-2g controller
// (docs/protocol.md, "Micro-2g"), offscreen on the manual clock: the rotor
// is turned by the switch on its control box (the simulator's hand drive),
// the page sets both stops and the range, reads them back, and afterwards
// the controller's heading is where the antenna really points. For a north
// stop and a south stop, a calibration the controller refuses, and a
// read-back that differs from what was sent.
#include "../common/simulatorpump.h"

#include "linkschemes.h"
#include "session/rotatorsession.h"
#include "sim/simulatorscheme.h"
#include "wizard/calibrationpage.h"
#include "wizard/setupwizard.h"

#include <QAbstractButton>
#include <QCheckBox>
#include <QDir>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTest>

#include <cmath>
#include <memory>

using namespace slew;
using session::RotatorSession;
using sim::Micro2gController;
using ui::CalibrationPage;
using ui::SetupWizard;
using Drive = Micro2gController::Drive;

namespace {

// Wall time to give up after. Every wait here is on the pumped clock, so
// what happens is the same at any speed; only how long it takes is not: a
// stop-to-stop turn is 1,500 rounds of the wizard's event loop, 18 s on a
// quiet machine, three times that sanitized beside other tests.
constexpr int kWaitMs = 90000;
// What the page says once the controller has taken a setting.
const QString kTaken = QStringLiteral("holds what was sent so far");
// The controller stops within its tolerance of a target: 20 counts, 5.8° on
// 1550 counts for 450°, and a count more for the reading's rounding.
constexpr double kToleranceDegrees = 6.5;

double angleBetween(double a, double b)
{
    const double d = std::fmod(std::abs(a - b), 360.0);
    return std::min(d, 360.0 - d);
}

} // namespace

class CalibrationPageTest : public QObject {
    Q_OBJECT

    // A session on the simulated controller and the wizard opened at the
    // calibration page, as the Identify page leaves it for a Micro-2g.
    struct Bench {
        RotatorSession session;
        std::unique_ptr<SetupWizard> wizard;
        sim::Simulator *sim = nullptr;
        CalibrationPage *page = nullptr;
        Micro2gController &controller() { return sim->micro2g(); }

        template<typename T>
        T *find(const char *name)
        {
            T *child = page->findChild<T *>(QLatin1String(name));
            if (!child)
                qWarning() << "no" << name << "on the calibration page";
            return child;
        }
        QString text(const char *label) { return find<QLabel>(label)->text(); }
        bool canGoOn() { return wizard->button(QWizard::NextButton)->isEnabled(); }
    };

    static bool open(Bench &b, const QString &uri)
    {
        model::RotatorProfile profile;
        profile.dialect = protocol::Dialect::Micro2g;
        b.session.setProfile(profile);
        b.session.connectTo(uri);
        // 50 ms slices (the controller itself steps by 10 ms within them):
        // a stop-to-stop turn is 75 simulated seconds.
        (new SimulatorPump(0.05, &b.session))->follow(&b.session);
        if (!runEventLoopUntil([&] { return b.session.capabilities().probed && b.session.hasPosition(); }, 10000))
            return false;
        b.sim = sim::simulatorBehind(b.session.link());
        b.wizard = std::make_unique<SetupWizard>(&b.session);
        b.wizard->setStartId(SetupWizard::CalibrationPageId);
        b.wizard->resize(900, 760);
        b.wizard->show();
        b.page = qobject_cast<CalibrationPage *>(b.wizard->currentPage());
        return b.sim && b.page;
    }

    // Holds the control box's switch until the rotor is at its stop, lets
    // go, and waits for the page to see it at rest.
    static bool turnToStop(Bench &b, int rotor, Drive way)
    {
        Micro2gController &c = b.controller();
        const double stop = way == Drive::Left ? 0.0 : 450.0;
        c.setHandDrive(rotor, way);
        const bool there = runEventLoopUntil([&] { return c.travel(rotor) == stop; }, kWaitMs);
        c.setHandDrive(rotor, Drive::Off);
        return there
            && runEventLoopUntil([&] { return b.text("adcReading").contains(QStringLiteral("at rest")); }, kWaitMs);
    }

    // The page's four steps with these bearings and range.
    static void calibrate(Bench &b, int rotor, int left, int right, int range)
    {
        QVERIFY(turnToStop(b, rotor, Drive::Left));
        b.find<QSpinBox>("leftBearing")->setValue(left);
        QTest::mouseClick(b.find<QPushButton>("setLeft"), Qt::LeftButton);
        TRY_VERIFY_WITH_TIMEOUT(b.text("calibrationStatus").contains(kTaken), kWaitMs);

        // Turning: the page says so and will not take a stop meanwhile.
        b.controller().setHandDrive(rotor, Drive::Right);
        TRY_VERIFY_WITH_TIMEOUT(b.text("adcReading").contains(QStringLiteral("turning")), kWaitMs);
        QVERIFY(!b.find<QPushButton>("setRight")->isEnabled());
        QVERIFY(turnToStop(b, rotor, Drive::Right));
        b.find<QSpinBox>("rightBearing")->setValue(right);
        QTest::mouseClick(b.find<QPushButton>("setRight"), Qt::LeftButton);
        TRY_VERIFY_WITH_TIMEOUT(b.text("calibrationStatus").contains(kTaken), kWaitMs);

        b.find<QSpinBox>("degreeRange")->setValue(range);
        QTest::mouseClick(b.find<QPushButton>("setRange"), Qt::LeftButton);
        TRY_VERIFY_WITH_TIMEOUT(b.canGoOn(), kWaitMs);
        QVERIFY(b.text("calibrationStatus").startsWith(QStringLiteral("Calibrated")));
    }

    // After calibrating: the heading the controller reads is where the
    // antenna points, at the stop and after a go-to.
    static void headingIsTrue(Bench &b, int rotor, double bearing)
    {
        Micro2gController &c = b.controller();
        TRY_VERIFY_WITH_TIMEOUT(angleBetween(b.session.azimuth(), c.trueBearing(rotor)) <= kToleranceDegrees
                                    && !b.session.positionStale(),
                                kWaitMs);
        QVERIFY(b.session.gotoPosition(bearing, 0));
        TRY_VERIFY_WITH_TIMEOUT(c.drive(rotor) != Drive::Off, kWaitMs);
        TRY_VERIFY2_WITH_TIMEOUT(c.drive(rotor) == Drive::Off
                                     && angleBetween(c.trueBearing(rotor), bearing) <= kToleranceDegrees,
                                 qPrintable(QStringLiteral("went to %1 for %2").arg(c.trueBearing(rotor)).arg(bearing)),
                                 kWaitMs);
        TRY_VERIFY_WITH_TIMEOUT(angleBetween(b.session.azimuth(), c.trueBearing(rotor)) <= kToleranceDegrees, kWaitMs);
    }

private slots:
    void initTestCase() { registerLinkSchemes(); }

    void northStopOnTheDefaultRotor()
    {
        // No rotor on the link: the page calibrates rotor 1 and says so.
        Bench b;
        QVERIFY(open(b, QStringLiteral("sim:?clock=manual&dialect=micro2g")));
        QVERIFY(b.text("calibrationRotor").contains(QStringLiteral("rotor 1")));
        QVERIFY(b.text("calibrationRotor").contains(QStringLiteral("names no rotor")));
        // A controller calibrated wrongly before: its heading is off.
        b.controller().handle(QStringLiteral("Z1L 3000=045"));
        QVERIFY(!b.canGoOn());

        calibrate(b, 1, 0, 90, 450);
        // What the controller holds is the example in docs/protocol.md.
        QVERIFY2(b.text("calibrationHeld").contains(QStringLiteral("Z1L 3990=000 Z1R 2440=090 Z1D 450")),
                 qPrintable(b.text("calibrationHeld")));
        QVERIFY(!b.text("calibrationHeld").contains(QStringLiteral("differs")));
        headingIsTrue(b, 1, 45);

        b.wizard->next();
        QCOMPARE(b.wizard->currentId(), int(SetupWizard::MechanicsPageId));
    }

    void southStopOnRotorTwo()
    {
        Bench b;
        QVERIFY(open(b, QStringLiteral("sim:?clock=manual&dialect=micro2g&rotor=2")));
        QCOMPARE(b.page->rotor(), 2);
        // Rotor 2 is built with its left stop pointing south; the
        // controller still holds the north-stop calibration.
        Micro2gController::Mechanics south;
        south.leftStopBearing = 180;
        b.controller().setMechanics(2, south);
        QVERIFY(angleBetween(b.controller().heading(2), b.controller().trueBearing(2)) > 90);

        calibrate(b, 2, 180, 270, 450);
        QVERIFY2(b.text("calibrationHeld").contains(QStringLiteral("Z2L 3990=180 Z2R 2440=270 Z2D 450")),
                 qPrintable(b.text("calibrationHeld")));
        headingIsTrue(b, 2, 200);
        QCOMPARE(b.controller().travel(1), 0.0); // the other rotors were left alone

        // A screenshot of the page as it ends, for a person to look at.
        QDir().mkpath(QStringLiteral(SLEW_SCREENSHOT_DIR));
        QVERIFY(b.wizard->grab().save(QStringLiteral(SLEW_SCREENSHOT_DIR "/calibration-page.png")));
    }

    void aRefusedCalibrationChangesNothing()
    {
        Bench b;
        QVERIFY(open(b, QStringLiteral("sim:?clock=manual&dialect=micro2g&rotor=3")));
        const sim::Micro2gCalibration before = b.controller().calibration(3);
        // The right stop set on the left stop's reading: both stops within
        // 10 counts, which the controller refuses.
        QVERIFY(turnToStop(b, 3, Drive::Left));
        QTest::mouseClick(b.find<QPushButton>("setRight"), Qt::LeftButton);
        TRY_VERIFY_WITH_TIMEOUT(b.text("calibrationStatus").contains(QStringLiteral("refused")), kWaitMs);
        QVERIFY2(b.text("calibrationStatus").contains(QStringLiteral("other stop")),
                 qPrintable(b.text("calibrationStatus")));
        const sim::Micro2gCalibration after = b.controller().calibration(3);
        QCOMPARE(after.rightAdc, before.rightAdc);
        QCOMPARE(after.rightBearing, before.rightBearing);
        QCOMPARE(after.leftAdc, before.leftAdc);
        // What the controller kept is read back, and nothing is flagged:
        // the refused stop is not counted as sent.
        TRY_VERIFY_WITH_TIMEOUT(b.text("calibrationHeld").contains(QStringLiteral("Z3R 2440=090")), kWaitMs);
        QVERIFY(!b.text("calibrationHeld").contains(QStringLiteral("differs")));
        QVERIFY(!b.canGoOn());
        // The page goes on working: the buttons are free again.
        TRY_VERIFY_WITH_TIMEOUT(b.find<QPushButton>("setLeft")->isEnabled(), kWaitMs);
        QDir().mkpath(QStringLiteral(SLEW_SCREENSHOT_DIR));
        QVERIFY(b.wizard->grab().save(QStringLiteral(SLEW_SCREENSHOT_DIR "/calibration-refused.png")));
    }

    void aReadBackThatDiffersIsFlagged()
    {
        Bench b;
        QVERIFY(open(b, QStringLiteral("sim:?clock=manual&dialect=micro2g&rotor=4")));
        calibrate(b, 4, 0, 90, 450);
        // Someone changes the range at the controller; Read back shows it.
        b.controller().handle(QStringLiteral("Z4D 360"));
        QTest::mouseClick(b.find<QPushButton>("readBack"), Qt::LeftButton);
        TRY_VERIFY_WITH_TIMEOUT(b.text("calibrationHeld").contains(QStringLiteral("Z4D 360")), kWaitMs);
        QVERIFY2(b.text("calibrationHeld").contains(QStringLiteral("differs: sent 450")),
                 qPrintable(b.text("calibrationHeld")));
        QVERIFY(!b.canGoOn());
        // Skipping is the operator's choice.
        b.find<QCheckBox>("skipCalibration")->setChecked(true);
        QVERIFY(b.canGoOn());
    }

    void onlyForControllersThatCalibrateByTheirStops()
    {
        RotatorSession session; // easycomm3, the profile's default
        SetupWizard wizard(&session);
        QVERIFY(!CalibrationPage::appliesTo(&wizard));
        wizard.profile().dialect = protocol::Dialect::Micro2g;
        QVERIFY(CalibrationPage::appliesTo(&wizard));
    }
};

QTEST_MAIN(CalibrationPageTest)
#include "tst_calibrationpage.moc"
