// SPDX-License-Identifier: GPL-3.0-or-later
// The operator window on a multi-rotor controller (the simulated Micro-2g,
// four rotors on one line): every rotor is shown and can be commanded
// without reconnecting, each through its own session on the one line; the
// window's Stop stops them all; a one-rotor controller shows no rotor tiles.

#include "windowfixture.h"

#include "model/savedcalibration.h"
#include "rotor/rotorspanel.h"
#include "rotor/rotortile.h"
#include "session/controllerrotors.h"
#include "sim/simulator.h"
#include "sim/simulatorscheme.h"
#include "stopbutton.h"
#include "transport/sharedline.h"
#include "widgets/compassdial.h"

#include <QLabel>
#include <QSettings>
#include <QToolButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>

using slew::session::RotatorSession;
using slew::sim::Micro2gController;
using slew::ui::RotorTile;

class MultiRotorWindowTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { WindowFixture::prepareApplication(); }
    // Saved calibrations outlive a test (test-mode settings): none is carried
    // into the next.
    void init() { QSettings().remove(QStringLiteral("calibration")); }
    void cleanup() { QSettings().remove(QStringLiteral("calibration")); }

    void showsAndCommandsEveryRotor()
    {
        WindowFixture f(QStringLiteral("sim:?dialect=micro2g&clock=manual&rotor=2"));
        QVERIFY(f.connectAndWait());
        slew::sim::Simulator *sim = slew::sim::simulatorBehind(f.session.link());
        QVERIFY(sim);
        slew::ui::RotorsPanel *panel = f.window->rotorsPanel();
        QVERIFY(panel->isVisibleTo(f.window.get()));
        QCOMPARE(panel->tiles().size(), 4);
        // Four tiles fit under the plot: the window needs no more width than without them.
        const int withTiles = f.window->minimumSizeHint().width();
        panel->hide();
        const int without = f.window->minimumSizeHint().width();
        panel->show();
        QVERIFY2(withTiles <= without, qPrintable(QStringLiteral("%1 > %2").arg(withTiles).arg(without)));
        QCOMPARE(f.session.rotor(), 2);
        QCOMPARE(panel->tile(2)->session(), &f.session); // the window's own rotor
        QVERIFY(panel->tile(2)->findChildren<QLabel *>().first()->text().contains(QStringLiteral("this window")));

        // The other three are sessions of their own, on the same line and simulator.
        for (int n : {1, 3, 4}) {
            RotatorSession *s = panel->tile(n)->session();
            QVERIFY(s != &f.session);
            QVERIFY(WindowFixture::waitFor([s] { return s->isConnected() && s->hasPosition() && !s->positionStale(); }, 10000));
            QCOMPARE(s->rotor(), n);
            QCOMPARE(slew::sim::simulatorBehind(s->link()), sim);
        }
        QVERIFY(f.window->controllerRotors()->line());
        QCOMPARE(slew::sim::simulatorBehind(f.window->controllerRotors()->line()->line()), sim);

        // Rotor 3, from its tile: it turns; the window's rotor does not.
        RotorTile *three = panel->tile(3);
        three->bearing()->setValue(60);
        QTest::mouseClick(three->goButton(), Qt::LeftButton);
        QVERIFY(WindowFixture::waitFor([&] { return sim->micro2g().drive(3) != Micro2gController::Drive::Off; }, 5000));
        QVERIFY(WindowFixture::waitFor([&] { return three->stateText().startsWith(QStringLiteral("turning to 60")); }, 10000));
        QVERIFY(WindowFixture::waitFor([&] {
            return sim->micro2g().drive(3) == Micro2gController::Drive::Off && std::abs(three->session()->azimuth() - 60) <= 6.5
                   && three->stateText() == QStringLiteral("at rest");
        }, 30000));
        QCOMPARE(three->headingText(), QStringLiteral("%1°").arg(std::lround(three->session()->azimuth())));
        QVERIFY(three->dial()->heading().has_value());
        QCOMPARE(*three->dial()->target(), 60.0);
        QCOMPARE(f.session.azimuth(), 0.0);
        QCOMPARE(sim->micro2g().travel(2), 0.0);

        // The window's own controls drive rotor 2 only.
        QVERIFY(f.session.gotoPosition(30, 0));
        QVERIFY(WindowFixture::waitFor([&] {
            return sim->micro2g().drive(2) == Micro2gController::Drive::Off && std::abs(f.session.azimuth() - 30) <= 6.5;
        }, 30000));
        QVERIFY(std::abs(panel->tile(2)->session()->azimuth() - 30) <= 6.5);
        QCOMPARE(sim->micro2g().travel(1), 0.0);

        // The window's Stop stops every rotor on the controller.
        panel->tile(1)->bearing()->setValue(200);
        QTest::mouseClick(panel->tile(1)->goButton(), Qt::LeftButton);
        panel->tile(4)->bearing()->setValue(200);
        QTest::mouseClick(panel->tile(4)->goButton(), Qt::LeftButton);
        QVERIFY(f.session.gotoPosition(200, 0));
        QVERIFY(WindowFixture::waitFor([&] {
            return sim->micro2g().travel(1) > 10 && sim->micro2g().travel(4) > 10 && sim->micro2g().travel(2) > 40;
        }, 20000));
        QTest::mouseClick(f.window->stopButton(), Qt::LeftButton);
        // Within half a simulated second (the time is the simulator's: in
        // two wall seconds these rotors would have reached 200° anyway).
        const double pressed = sim->clock().now();
        QVERIFY(WindowFixture::waitFor([&] { return sim->clock().now() > pressed + 0.5; }, 5000));
        for (int n = 1; n <= 4; ++n)
            QVERIFY2(sim->micro2g().drive(n) == Micro2gController::Drive::Off, qPrintable(QStringLiteral("rotor %1").arg(n)));
        // And they stay stopped: two simulated seconds later, not a degree more.
        const double one = sim->micro2g().travel(1), four = sim->micro2g().travel(4);
        const double then = sim->clock().now();
        QVERIFY(WindowFixture::waitFor([&] { return sim->clock().now() > then + 2; }, 5000));
        QCOMPARE(sim->micro2g().travel(1), one);
        QCOMPARE(sim->micro2g().travel(4), four);

        // A rotor's own Stop stops that rotor alone.
        three->bearing()->setValue(150);
        QTest::mouseClick(three->goButton(), Qt::LeftButton);
        QVERIFY(f.session.gotoPosition(120, 0));
        QVERIFY(WindowFixture::waitFor([&] {
            return sim->micro2g().drive(3) != Micro2gController::Drive::Off && sim->micro2g().drive(2) != Micro2gController::Drive::Off;
        }, 5000));
        QTest::mouseClick(three->stopButton(), Qt::LeftButton);
        const double stopped = sim->clock().now();
        QVERIFY(WindowFixture::waitFor([&] { return sim->clock().now() > stopped + 0.5; }, 5000));
        QCOMPARE(sim->micro2g().drive(3), Micro2gController::Drive::Off);
        QVERIFY(sim->micro2g().drive(2) != Micro2gController::Drive::Off);
        QVERIFY(f.session.stop(QStringLiteral("the test")));

        // Disconnecting takes the others along, and the tiles go.
        f.session.disconnectFromRotator();
        QVERIFY(panel->tiles().isEmpty());
        QVERIFY(!panel->isVisibleTo(f.window.get()));
    }

    // Each rotor on the line turns its own antenna: the calibration found
    // for one (sun or moon alignment) is not the others'. Each takes the
    // offsets saved for its own URI, whatever order its query was typed in.
    void eachRotorKeepsItsOwnCalibration()
    {
        const QString uri = QStringLiteral("sim:?dialect=micro2g&clock=manual&rotor=2");
        slew::model::saveCalibration(uri, {2.0, 0.0});
        slew::model::saveCalibration(QStringLiteral("sim:?rotor=3&dialect=micro2g&clock=manual"), {5.0, 0.0});
        WindowFixture f(uri);
        QVERIFY(f.connectAndWait());
        slew::ui::RotorsPanel *panel = f.window->rotorsPanel();
        QCOMPARE(panel->tiles().size(), 4);
        QCOMPARE(f.session.profile().azOffsetDeg, 2.0);
        QCOMPARE(panel->tile(1)->session()->profile().azOffsetDeg, 0.0);
        QCOMPARE(panel->tile(3)->session()->profile().azOffsetDeg, 5.0);
        QCOMPARE(panel->tile(4)->session()->profile().azOffsetDeg, 0.0);

        // Rotor 3 pointed at 100° is its controller's 95°.
        RotatorSession *three = panel->tile(3)->session();
        QVERIFY(WindowFixture::waitFor([three] { return three->isConnected() && three->hasPosition(); }, 10000));
        QSignalSpy sent(three, &RotatorSession::bytesSent);
        QVERIFY(three->gotoPosition(100, 0));
        QCOMPARE(sent.first().at(0).toByteArray(), QByteArray("3\rM095\r"));

        // A change to the controller's profile (here the window's rotor
        // aligned again) leaves the others' calibration as it was.
        slew::model::RotatorProfile profile = f.session.profile();
        profile.azOffsetDeg = -1.5;
        f.session.setProfile(profile);
        QCOMPARE(panel->tile(1)->session()->profile().azOffsetDeg, 0.0);
        QCOMPARE(panel->tile(3)->session()->profile().azOffsetDeg, 5.0);
        QVERIFY(three->stop(QStringLiteral("the test")));
    }

    void aRefusedMoveIsShownOnItsTile()
    {
        WindowFixture f(QStringLiteral("sim:?dialect=micro2g&clock=manual&rotor=1"));
        QVERIFY(f.connectAndWait());
        slew::ui::RotorsPanel *panel = f.window->rotorsPanel();
        RotorTile *four = panel->tile(4);
        QVERIFY(four);
        QVERIFY(WindowFixture::waitFor([&] { return four->session()->isConnected(); }, 10000));
        // The operator narrows the travel: every rotor's session takes it,
        // and rotor 4's tile is refused by the same gate as the window.
        slew::model::RotatorProfile profile = f.session.profile();
        profile.limits.azMax = 90;
        f.session.setProfile(profile);
        QCOMPARE(four->session()->profile().limits.azMax, 90.0);
        QSignalSpy sent(four->session(), &RotatorSession::bytesSent);
        four->bearing()->setValue(180);
        QTest::mouseClick(four->goButton(), Qt::LeftButton);
        QVERIFY2(four->stateText().contains(QStringLiteral("180")), qPrintable(four->stateText()));
        QVERIFY(!four->stateText().startsWith(QStringLiteral("turning")));
        QVERIFY(WindowFixture::waitFor([&] { return sent.count() >= 2; }, 5000)); // polls go on
        for (const auto &args : sent)
            QVERIFY2(!args.at(0).toByteArray().contains('M'), args.at(0).toByteArray().constData());
        // A move inside the limits goes, and the message makes way for it.
        four->bearing()->setValue(20);
        QTest::mouseClick(four->goButton(), Qt::LeftButton);
        QVERIFY(!four->stateText().contains(QStringLiteral("180")));
    }

    void aOneRotorControllerShowsNoTiles()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        QVERIFY(f.window->rotorsPanel()->tiles().isEmpty());
        QVERIFY(!f.window->rotorsPanel()->isVisibleTo(f.window.get()));
        // Its link is its own, not a shared line's.
        QVERIFY(!f.window->controllerRotors()->line());
    }
};

QTEST_MAIN(MultiRotorWindowTest)
#include "tst_multirotorwindow.moc"
