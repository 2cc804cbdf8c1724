// SPDX-License-Identifier: GPL-3.0-or-later
// Link loss, operator disconnects and homing, each against a simulator set
// up to produce the situation (drop_after, start position, missing switch).
// Every simulator runs on its manual clock, pumped by the fixture: staleness,
// homing and parking take simulated seconds, not wall-clock ones.

#include "windowfixture.h"

#include "alarmbanner.h"
#include "rotor/connectionbar.h"
#include "rotor/parkhomepanel.h"
#include "rotor/polarplotwidget.h"
#include "sim/simulator.h"
#include "sim/simulatorscheme.h"
#include "widgets/elidinglabel.h"

#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QStatusBar>
#include <QRegularExpression>
#include <QTest>

class TestAlarmsAndHoming : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { WindowFixture::prepareApplication(); }

    void aLostLinkRaisesTheBannerAndShowsLost()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        // The cut comes once the link is up. drop_after counts from when the
        // link opened, so `sim:?drop_after=1` raced the probe and the first
        // positions, and lost on a busy machine.
        slew::sim::Simulator *simulator = slew::sim::simulatorBehind(f.session.link());
        QVERIFY(simulator);
        slew::sim::LinkFaults faults;
        faults.dropAfter = 0.001;
        simulator->setLinkFaults(faults);
        QVERIFY(f.waitFor([&] { return f.window->alarmBanner()->text().contains(QStringLiteral("Link lost")); }, 10000));
        QVERIFY(f.window->alarmBanner()->isSevere());
        QCOMPARE(f.find<QLabel>(QStringLiteral("connectionState"))->text(), QStringLiteral("lost"));
    }

    void aSilentControllerMakesThePositionStale()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        QVERIFY(f.session.gotoPosition(20, 10));
        QVERIFY(f.waitUntilAt(20, 10));
        QVERIFY(f.waitFor([&] { return f.window->alarmBanner()->isHidden(); }, 5000));
        // The link stays up but every answer is lost, as with a dead controller
        // behind a live serial adapter.
        slew::sim::Simulator *simulator = slew::sim::simulatorBehind(f.session.link());
        QVERIFY(simulator);
        slew::sim::LinkFaults faults;
        faults.dropRate = 1.0;
        simulator->setLinkFaults(faults);
        QVERIFY(f.waitFor([&] { return f.window->alarmBanner()->text().contains(QStringLiteral("stale")); }, 10000));
        QVERIFY(f.window->alarmBanner()->isSevere());
        QVERIFY(f.session.positionStale());
        // Answers come back: the alarm clears.
        simulator->setLinkFaults({});
        QVERIFY(f.waitFor([&] { return !f.window->alarmBanner()->text().contains(QStringLiteral("stale")); }, 10000));
    }

    void anOperatorDisconnectIsNotAnAlarm()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        QVERIFY(f.session.gotoPosition(20, 10)); // off the end stops, so no warning holds
        QVERIFY(f.waitUntilAt(20, 10));
        QVERIFY(f.waitFor([&] { return f.window->alarmBanner()->isHidden(); }, 5000));
        QTest::mouseClick(f.find<QPushButton>(QStringLiteral("connectButton")), Qt::LeftButton);
        QCOMPARE(f.session.state(), slew::session::RotatorSession::State::Disconnected);
        QVERIFY(f.window->alarmBanner()->isHidden());
        QCOMPARE(f.find<QLabel>(QStringLiteral("connectionState"))->text(), QStringLiteral("disconnected"));
        QCOMPARE(slew::ui::ConnectionBar::rememberedUri(), f.uri);
    }

    void theDefaultSimulatorOpensWithoutABanner()
    {
        // It rests at 0/0 on both lower limit switches, as many rotators park:
        // a state for the status line, not an alarm.
        WindowFixture f(QStringLiteral("sim:?clock=manual"));
        QVERIFY(f.connectAndWait());
        auto *resting = f.find<slew::ui::ElidingLabel>(QStringLiteral("limitSwitchState"));
        QVERIFY(f.waitFor([&] { return resting->fullText().contains(QStringLiteral("limit switch")); }, 5000));
        QVERIFY(f.window->alarmBanner()->isHidden());
        QVERIFY(f.window->alarmBanner()->text().isEmpty());
        // Said once, at the foot, not also as a passing message beside it.
        QVERIFY2(!f.window->statusBar()->currentMessage().contains(QStringLiteral("limit switch")),
                 qPrintable(f.window->statusBar()->currentMessage()));
        // Moving off the switches ends the quiet state too.
        QVERIFY(f.session.gotoPosition(3, 2));
        QVERIFY(f.waitUntilAt(3, 2, 0.2));
        QVERIFY(f.waitFor([&] { return resting->fullText().isEmpty(); }, 5000));
        QVERIFY(f.window->alarmBanner()->isHidden());
    }

    void aMoveIntoTheStopItRestsOnRaisesTheBannerUntilTheNextMove()
    {
        WindowFixture f(QStringLiteral("sim:?clock=manual"));
        QVERIFY(f.connectAndWait());
        auto *resting = f.find<slew::ui::ElidingLabel>(QStringLiteral("limitSwitchState"));
        QVERIFY(f.waitFor([&] { return resting->fullText().contains(QStringLiteral("limit switch")); }, 5000));
        QVERIFY(f.window->alarmBanner()->isHidden());
        // At rest on the counter-clockwise stop, the operator holds ◀.
        const QRegularExpression jogLeft(QStringLiteral("^VL"));
        auto *left = f.find<QPushButton>(QStringLiteral("jogLeft"));
        QTest::mousePress(left, Qt::LeftButton);
        QVERIFY(f.waitFor([&] { return !f.window->alarmBanner()->isHidden(); }, 5000));
        QTest::mouseRelease(left, Qt::LeftButton);
        QVERIFY2(f.window->alarmBanner()->text().contains(QStringLiteral("Move refused: azimuth is already at its lower limit")),
                 qPrintable(f.window->alarmBanner()->text()));
        QVERIFY(!f.window->alarmBanner()->isSevere()); // a warning
        QCOMPARE(f.sentCount(jogLeft), 0);
        // A move the session sends clears it.
        QVERIFY(f.session.gotoPosition(2, 1));
        QVERIFY(f.waitFor([&] { return f.window->alarmBanner()->isHidden(); }, 5000));

        // A tracker's target beyond the limits is refused the same way.
        QVERIFY(!f.session.gotoPosition(10, 95));
        QVERIFY2(f.window->alarmBanner()->text().contains(QStringLiteral("Move refused")),
                 qPrintable(f.window->alarmBanner()->text()));
        QVERIFY(f.session.gotoPosition(3, 2));
        QVERIFY(f.waitFor([&] { return f.window->alarmBanner()->isHidden(); }, 5000));
    }

    void drivingIntoAnEndStopRaisesTheBanner()
    {
        WindowFixture f(QStringLiteral("sim:?model=satnogs&start_az=330&start_el=20&clock=manual"));
        QVERIFY(f.connectAndWait());
        QVERIFY(f.window->alarmBanner()->isHidden());
        // A raw speed command the profile's soft limits cannot stop: the
        // switch at 360 has to.
        QVERIFY(f.session.sendRaw(QStringLiteral("VR20000")));
        QVERIFY(f.waitFor([&] { return f.window->alarmBanner()->text().contains(QStringLiteral("end stop")); }, 30000));
        QVERIFY(!f.window->alarmBanner()->isHidden());
        QVERIFY(!f.window->alarmBanner()->isSevere()); // a warning, not a fault
        f.session.stop(QStringLiteral("the test"));
    }

    void homingShowsProgressUntilIdle()
    {
        WindowFixture f(QStringLiteral("sim:?start_az=6&start_el=4&clock=manual"));
        QVERIFY(f.connectAndWait());
        QTest::mouseClick(f.find<QPushButton>(QStringLiteral("homeButton")), Qt::LeftButton);
        auto *panel = f.window->parkHomePanel();
        QVERIFY(panel->isHoming());
        QVERIFY(!f.find<QProgressBar>(QStringLiteral("homeProgress"))->isHidden());
        QVERIFY(f.sentCount(QRegularExpression(QStringLiteral("^RESET$"))) == 1);
        QVERIFY(f.waitFor([&] { return !panel->isHoming(); }, 30000));
        QCOMPARE(f.find<QLabel>(QStringLiteral("homeMessage"))->text(), QStringLiteral("Homed."));
        QVERIFY(f.find<QProgressBar>(QStringLiteral("homeProgress"))->isHidden());
        QCOMPARE_LE(f.session.azimuth(), 0.5);
        QCOMPARE_LE(f.session.elevation(), 0.5);
    }

    void parkGoesToThePark()
    {
        WindowFixture f(QStringLiteral("sim:?park_az=45&park_el=10&clock=manual"));
        QVERIFY(f.connectAndWait());
        QTest::mouseClick(f.find<QPushButton>(QStringLiteral("parkButton")), Qt::LeftButton);
        QCOMPARE(f.sentCount(QRegularExpression(QStringLiteral("^PARK$"))), 1);
        QVERIFY(f.waitUntilAt(45, 10));
    }

    void aHomingShorterThanTheStatusPollIsSeen()
    {
        // A second of homing from a few degrees off the switches, and GS asked
        // only every five seconds: the homing starts and ends between two
        // status answers, which a loaded machine makes likely at the usual
        // rate too. The moving position shows it ran.
        WindowFixture f(QStringLiteral("sim:?start_az=6&start_el=4&clock=manual"));
        slew::session::RotatorSession::Options options = f.session.options();
        options.telemetryEvery = 50;
        f.session.setOptions(options);
        QVERIFY(f.connectAndWait());
        auto *panel = f.window->parkHomePanel();
        QVERIFY(panel->home());
        QVERIFY(f.waitFor([&] { return !panel->isHoming(); }, 60000));
        QCOMPARE(f.find<QLabel>(QStringLiteral("homeMessage"))->text(), QStringLiteral("Homed."));
        QCOMPARE_LE(f.session.azimuth(), 0.5);
        QCOMPARE_LE(f.session.elevation(), 0.5);
    }
};

QTEST_MAIN(TestAlarmsAndHoming)
#include "tst_alarmsandhoming.moc"
