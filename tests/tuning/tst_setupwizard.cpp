// SPDX-License-Identifier: GPL-3.0-or-later
// The setup wizard driven end to end offscreen against the simulator: every
// page, the wizard's STOP during homing (the rotator stops), a homing
// failure injected in the simulator (the wizard says so), tuning with before
// and after, and the summary's write, read-back and profile save; the
// summary's register names, and Finish only once the registers read back;
// no tuning or speed measurement while a rehearsal runs the simulator
// faster than real time, and the page says why.
#include "../common/simulatorpump.h"

#include "linkschemes.h"
#include "session/rotatorsession.h"
#include "sim/simulatorscheme.h"
#include "sky/utctime.h"
#include "tracking/simulatorpace.h"
#include "tracking/stationclock.h"
#include "wizard/setupwizard.h"

#include <QAbstractButton>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QDoubleSpinBox>

#include <memory>

using namespace slew;
using session::RotatorSession;
using ui::SetupWizard;

class TestSetupWizard : public QObject {
    Q_OBJECT

    template<typename T>
    T *find(SetupWizard &w, const char *name)
    {
        T *child = w.currentPage()->findChild<T *>(QLatin1String(name));
        if (!child)
            qWarning() << "no" << name << "on page" << w.currentId();
        return child;
    }
    static bool canGoOn(SetupWizard &w) { return w.button(QWizard::NextButton)->isEnabled(); }

    // From Connect through Identify, as an operator would: the probe must
    // get an answer, then the identification runs on the wall clock (the
    // line dialects' attempts must time out). The Identify page's result,
    // or empty when a page did not let the wizard go on.
    QString connectAndIdentify(SetupWizard &wizard, const QString &uri)
    {
        find<QLineEdit>(wizard, "uri")->setText(uri);
        QTest::mouseClick(find<QPushButton>(wizard, "probe"), Qt::LeftButton);
        if (!QTest::qWaitFor([&] { return canGoOn(wizard); }, 10000)
            || !find<QListWidget>(wizard, "baudResults")->item(0)->text().contains(QStringLiteral("answered")))
            return {};
        wizard.next();
        if (wizard.currentId() != int(SetupWizard::IdentifyPageId) || !QTest::qWaitFor([&] { return canGoOn(wizard); }, 60000))
            return {};
        return find<QLabel>(wizard, "dialectResult")->text();
    }

private slots:
    void initTestCase() { registerLinkSchemes(); }

    void everyPage()
    {
        RotatorSession session;
        SetupWizard wizard(&session);
        wizard.resize(900, 760);
        wizard.show();
        // 20 ms slices: the two tuning runs are many simulated seconds, and
        // the figures are the 5 ms pump's (rise 0.38 s, overshoot 47.5 %).
        SimulatorPump pump(0.02);

        // Connect: probe the link.
        QCOMPARE(wizard.currentId(), int(SetupWizard::ConnectPageId));
        find<QLineEdit>(wizard, "uri")->setText(
            QStringLiteral("sim:?clock=manual&unsolicited=1&kp=12&ki=1&kd=1&start_az=12&start_el=6"));
        QVERIFY(!canGoOn(wizard));
        QTest::mouseClick(find<QPushButton>(wizard, "probe"), Qt::LeftButton);
        TRY_VERIFY_WITH_TIMEOUT(canGoOn(wizard), 10000);
        QVERIFY(find<QListWidget>(wizard, "baudResults")->item(0)->text().contains(QStringLiteral("answered")));
        wizard.next();

        // Identify: easycomm3, and the session is connected with it.
        QCOMPARE(wizard.currentId(), int(SetupWizard::IdentifyPageId));
        TRY_VERIFY_WITH_TIMEOUT(canGoOn(wizard), 30000);
        QVERIFY(find<QLabel>(wizard, "dialectResult")->text().contains(QStringLiteral("easycomm3")));
        sim::Simulator *sim = sim::simulatorBehind(session.link());
        QVERIFY(sim);
        pump.drive(sim);
        wizard.next();

        // Mechanics: a jog the operator confirms.
        QCOMPARE(wizard.currentId(), int(SetupWizard::MechanicsPageId));
        QVERIFY(!canGoOn(wizard));
        QTest::mouseClick(find<QPushButton>(wizard, "jog"), Qt::LeftButton);
        TRY_VERIFY_WITH_TIMEOUT(std::fabs(session.azimuth() - 17.0) < 0.2, 10000);
        find<QCheckBox>(wizard, "jogConfirmed")->setChecked(true);
        QTest::mouseClick(find<QPushButton>(wizard, "jogElevation"), Qt::LeftButton);
        TRY_VERIFY_WITH_TIMEOUT(std::fabs(session.elevation() - 11.0) < 0.2, 10000);
        find<QCheckBox>(wizard, "jogElevationConfirmed")->setChecked(true);
        QVERIFY(canGoOn(wizard));
        wizard.next();

        // Homing: stopped part way with the wizard's STOP, and the rotator stops.
        QCOMPARE(wizard.currentId(), int(SetupWizard::HomingPageId));
        QVERIFY(!canGoOn(wizard));
        auto *stop = wizard.findChild<QPushButton *>(QStringLiteral("wizardStop"));
        auto *home = find<QPushButton>(wizard, "home");
        auto *result = find<QLabel>(wizard, "homingResult");
        auto cancelAt = connect(&session, &RotatorSession::positionChanged, this, [&](double az, double, bool) {
            if (az < 14.0 && !home->isEnabled())
                QTest::mouseClick(stop, Qt::LeftButton);
        });
        QTest::mouseClick(find<QPushButton>(wizard, "home"), Qt::LeftButton);
        TRY_VERIFY_WITH_TIMEOUT(result->text().contains(QStringLiteral("cancelled")), 10000);
        disconnect(cancelAt);
        TRY_VERIFY_WITH_TIMEOUT(sim->rotator().axis(sim::Axis::Azimuth).isStopped(), 5000);
        QVERIFY(sim->rotator().axis(sim::Axis::Elevation).isStopped());
        QVERIFY(session.azimuth() > 5.0);
        QVERIFY(!canGoOn(wizard));

        // Homing: the azimuth end stop is missing, and the wizard says so.
        sim::AxisFaults broken;
        broken.missingEndStop = true;
        sim->setAxisFaults(sim::Axis::Azimuth, broken);
        QTest::mouseClick(find<QPushButton>(wizard, "home"), Qt::LeftButton);
        TRY_VERIFY_WITH_TIMEOUT(result->text().contains(QStringLiteral("homing error")), 20000);
        QVERIFY(result->text().contains(QStringLiteral("end stop")));
        QVERIFY(!canGoOn(wizard));

        // Homing: switch repaired, it homes.
        sim->setAxisFaults(sim::Axis::Azimuth, sim::AxisFaults{});
        QTest::mouseClick(find<QPushButton>(wizard, "home"), Qt::LeftButton);
        TRY_VERIFY_WITH_TIMEOUT(canGoOn(wizard), 20000);
        QVERIFY(result->text().contains(QStringLiteral("Homed")));
        wizard.next();

        // Tuning: azimuth accepted, elevation kept as it was.
        QCOMPARE(wizard.currentId(), int(SetupWizard::TuningPageId));
        auto *accept = find<QPushButton>(wizard, "accept");
        QTest::mouseClick(find<QPushButton>(wizard, "tune"), Qt::LeftButton);
        TRY_VERIFY2_WITH_TIMEOUT(accept->isEnabled(), qPrintable(find<QLabel>(wizard, "tuningStatus")->text()), 60000);
        QVERIFY(!canGoOn(wizard));
        QVERIFY(find<QLabel>(wizard, "beforeFigures")->text().contains(QStringLiteral("overshoot")));
        QVERIFY(find<QLabel>(wizard, "afterFigures")->text().contains(QStringLiteral("settling time")));
        const QString shot = QStringLiteral(SLEW_SCREENSHOT_DIR "/tuning-before-after.png");
        QDir().mkpath(QStringLiteral(SLEW_SCREENSHOT_DIR));
        QVERIFY(wizard.grab().save(shot));
        QTest::mouseClick(accept, Qt::LeftButton);
        TRY_VERIFY_WITH_TIMEOUT(canGoOn(wizard), 5000);
        const double acceptedKd = sim->rotator().axis(sim::Axis::Azimuth).gains().kd;
        QVERIFY(acceptedKd > 2.0);

        find<QComboBox>(wizard, "axis")->setCurrentIndex(1);
        QTest::mouseClick(find<QPushButton>(wizard, "tune"), Qt::LeftButton);
        TRY_VERIFY_WITH_TIMEOUT(accept->isEnabled(), 60000);
        QTest::mouseClick(find<QPushButton>(wizard, "keepOld"), Qt::LeftButton);
        TRY_VERIFY_WITH_TIMEOUT(canGoOn(wizard), 5000);
        QCOMPARE(sim->rotator().axis(sim::Axis::Elevation).gains().kd, 1.0);

        // The elevation's speed for the tracker: a 30° move, measured.
        QTest::mouseClick(find<QPushButton>(wizard, "measureSpeed"), Qt::LeftButton);
        TRY_VERIFY2_WITH_TIMEOUT(find<QLabel>(wizard, "tuningStatus")->text().contains(QStringLiteral("turns at")),
                                 qPrintable(find<QLabel>(wizard, "tuningStatus")->text()), 60000);
        TRY_VERIFY_WITH_TIMEOUT(canGoOn(wizard), 5000);
        wizard.next();

        // Park: from the present position, nudged by hand.
        QCOMPARE(wizard.currentId(), int(SetupWizard::ParkPageId));
        QTest::mouseClick(find<QPushButton>(wizard, "useCurrent"), Qt::LeftButton);
        find<QDoubleSpinBox>(wizard, "parkAz")->setValue(180.0);
        find<QDoubleSpinBox>(wizard, "parkEl")->setValue(45.0);
        wizard.next();

        // Summary: write, read back each register, save.
        QCOMPARE(wizard.currentId(), int(SetupWizard::SummaryPageId));
        QVERIFY(find<QLabel>(wizard, "plan")->text().contains(QStringLiteral("Az park: 180°")));
        QVERIFY(!wizard.button(QWizard::FinishButton)->isEnabled());
        QTest::mouseClick(find<QPushButton>(wizard, "write"), Qt::LeftButton);
        auto *list = find<QListWidget>(wizard, "writeResults");
        TRY_COMPARE_WITH_TIMEOUT(list->count(), 8, 10000);
        for (int i = 0; i < list->count(); ++i)
            QVERIFY2(list->item(i)->text().endsWith(QStringLiteral("ok")), qPrintable(list->item(i)->text()));
        QVERIFY(wizard.button(QWizard::FinishButton)->isEnabled());
        QCOMPARE(sim->rotator().config().parkAzimuth, 180.0);
        QCOMPARE(sim->rotator().config().parkElevation, 45.0);

        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("rotator.json"));
        find<QLineEdit>(wizard, "profilePath")->setText(path);
        QSignalSpy saved(&wizard, &SetupWizard::profileSaved);
        QTest::mouseClick(find<QPushButton>(wizard, "save"), Qt::LeftButton);
        QCOMPARE(saved.count(), 1);
        QString error;
        const auto profile = model::RotatorProfile::load(path, &error);
        QVERIFY2(profile, qPrintable(error));
        QCOMPARE(profile->parkAz, 180.0);
        QVERIFY(profile->azGains);
        QCOMPARE(profile->azGains->kd, acceptedKd);
        QCOMPARE(profile->elGains->kd, 1.0);
        QCOMPARE(profile->dialect, protocol::Dialect::Easycomm3);
        // The simulated G-5500's elevation, as measured: its speed, and how
        // fast these (stiff) gains get it there, in place of the profile's
        // own 6°/s². (The delay depends on when the polls land.)
        QVERIFY2(std::abs(profile->motion.elSpeedDegS - 2.7) < 0.1, qPrintable(QString::number(profile->motion.elSpeedDegS)));
        QVERIFY2(profile->motion.elAccelDegS2 > 0 && profile->motion.elAccelDegS2 != 6.0,
                 qPrintable(QString::number(profile->motion.elAccelDegS2)));
        QVERIFY(profile->motion.responseDelayS < 0.5);
    }

    void aMicro2gIsWalkedToItsCalibrationPage()
    {
        // From Connect, as an operator would: the probe and the
        // identification learn the Micro-2g, and its calibration page follows.
        RotatorSession session;
        SetupWizard wizard(&session);
        wizard.show();
        // Nothing here pumps the simulators the attempts open.
        const QString identified = connectAndIdentify(wizard, QStringLiteral("sim:?dialect=micro2g&rotor=3"));
        QVERIFY2(identified.contains(QStringLiteral("micro2g")), qPrintable(identified));
        QCOMPARE(session.profile().dialect, protocol::Dialect::Micro2g);
        wizard.next();
        QCOMPARE(wizard.currentId(), int(SetupWizard::CalibrationPageId));
    }

    void aRot2ProgIsWalkedToItsProfile()
    {
        // A SPID controller, from Connect to the saved profile: identified by
        // its binary answers, jogged, homing skipped (it has none), its
        // speed measured (in the controller's half-degree steps), and no
        // registers written: the park position is the profile's. On the
        // wall clock, as for the Micro-2g.
        RotatorSession session;
        SetupWizard wizard(&session);
        wizard.show();
        const QString identified = connectAndIdentify(wizard, QStringLiteral("sim:?dialect=rot2prog&start_az=12&start_el=6"));
        QVERIFY2(identified.contains(QStringLiteral("rot2prog")) && identified.contains(QStringLiteral("md01")),
                 qPrintable(identified));
        TRY_VERIFY_WITH_TIMEOUT(session.capabilities().probed && session.hasPosition(), 10000);
        wizard.next();

        QCOMPARE(wizard.currentId(), int(SetupWizard::MechanicsPageId));
        QTest::mouseClick(find<QPushButton>(wizard, "jog"), Qt::LeftButton);
        TRY_VERIFY_WITH_TIMEOUT(std::fabs(session.azimuth() - 17.0) < 0.5, 10000);
        find<QCheckBox>(wizard, "jogConfirmed")->setChecked(true);
        QTest::mouseClick(find<QPushButton>(wizard, "jogElevation"), Qt::LeftButton);
        TRY_VERIFY_WITH_TIMEOUT(std::fabs(session.elevation() - 11.0) < 0.5, 10000);
        find<QCheckBox>(wizard, "jogElevationConfirmed")->setChecked(true);
        wizard.next();

        QCOMPARE(wizard.currentId(), int(SetupWizard::HomingPageId));
        QVERIFY(!find<QPushButton>(wizard, "home")->isEnabled()); // no homing command: skipped, and said so
        QVERIFY(find<QCheckBox>(wizard, "skipHoming")->isChecked());
        QVERIFY(find<QLabel>(wizard, "homingResult")->text().contains(QStringLiteral("no homing command")));
        TRY_VERIFY_WITH_TIMEOUT(canGoOn(wizard), 5000);
        wizard.next();

        QCOMPARE(wizard.currentId(), int(SetupWizard::TuningPageId));
        QVERIFY(!find<QPushButton>(wizard, "tune")->isEnabled()); // no gain registers
        QTest::mouseClick(find<QPushButton>(wizard, "measureSpeed"), Qt::LeftButton);
        TRY_VERIFY2_WITH_TIMEOUT(find<QLabel>(wizard, "tuningStatus")->text().contains(QStringLiteral("turns at")),
                                 qPrintable(find<QLabel>(wizard, "tuningStatus")->text()), 60000);
        TRY_VERIFY_WITH_TIMEOUT(canGoOn(wizard), 5000);
        wizard.next();

        QCOMPARE(wizard.currentId(), int(SetupWizard::ParkPageId));
        QVERIFY2(wizard.currentPage()->subTitle().contains(QStringLiteral("no park registers")),
                 qPrintable(wizard.currentPage()->subTitle()));
        find<QDoubleSpinBox>(wizard, "parkAz")->setValue(180.0);
        find<QDoubleSpinBox>(wizard, "parkEl")->setValue(45.0);
        wizard.next();

        QCOMPARE(wizard.currentId(), int(SetupWizard::SummaryPageId));
        const QString plan = find<QLabel>(wizard, "plan")->text();
        QVERIFY2(plan.contains(QStringLiteral("no configuration registers")) && !plan.contains(QStringLiteral("CW")),
                 qPrintable(plan));
        QVERIFY(!find<QPushButton>(wizard, "write")->isEnabled());
        QVERIFY(wizard.button(QWizard::FinishButton)->isEnabled()); // nothing to write, nothing to wait for
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("rotator.json"));
        find<QLineEdit>(wizard, "profilePath")->setText(path);
        QTest::mouseClick(find<QPushButton>(wizard, "save"), Qt::LeftButton);
        QString error;
        const auto profile = model::RotatorProfile::load(path, &error);
        QVERIFY2(profile, qPrintable(error));
        QCOMPARE(profile->dialect, protocol::Dialect::Rot2Prog);
        QCOMPARE(profile->parkAz, 180.0);
        // The simulated G-5500's azimuth, measured through SPID's half-degree steps.
        QVERIFY2(std::abs(profile->motion.azSpeedDegS - 6.2) < 0.3, qPrintable(QString::number(profile->motion.azSpeedDegS)));
        wizard.reject();
    }

    void theSummaryNamesWhatItWrites()
    {
        // "Az I gain: 1", "El park: 45°": what the operator set, in the
        // operator's words, before and after it was written.
        std::unique_ptr<RotatorSession> session;
        std::unique_ptr<SimulatorPump> pump;
        QVERIFY(connectPumped(QStringLiteral("sim:?clock=manual&unsolicited=1"), session, pump));
        model::RotatorProfile profile = session->profile();
        profile.azGains = model::PidGains{12.5, 1, 1};
        profile.elGains = model::PidGains{10, 0.5, 2};
        profile.parkAz = 180;
        profile.parkEl = 45;
        session->setProfile(profile);
        SetupWizard wizard(session.get());
        wizard.setStartId(SetupWizard::SummaryPageId);
        wizard.show();
        const QString plan = find<QLabel>(wizard, "plan")->text();
        for (const char *line : {"Az P gain: 12.5", "Az I gain: 1", "Az D gain: 1", "El P gain: 10", "El I gain: 0.5",
                                 "El D gain: 2", "Az park: 180°", "El park: 45°"})
            QVERIFY2(plan.contains(QString::fromUtf8(line)), qPrintable(plan));
        QVERIFY2(!plan.contains(QStringLiteral("CW")), qPrintable(plan));

        QTest::mouseClick(find<QPushButton>(wizard, "write"), Qt::LeftButton);
        auto *list = find<QListWidget>(wizard, "writeResults");
        TRY_COMPARE(list->count(), 8);
        // The controller prints its own decimals ("1.000", "45.00").
        const QString gain = list->item(1)->text(), park = list->item(7)->text();
        QVERIFY2(gain.startsWith(QStringLiteral("Az I gain: wrote 1, reads 1.0")) && gain.endsWith(QStringLiteral(" — ok")),
                 qPrintable(gain));
        QVERIFY2(park.startsWith(QStringLiteral("El park: wrote 45°, reads 45.0")) && park.endsWith(QStringLiteral("° — ok")),
                 qPrintable(park));
        for (int i = 0; i < list->count(); ++i)
            QVERIFY2(!list->item(i)->text().contains(QStringLiteral("CR")), qPrintable(list->item(i)->text()));
    }

    void finishWaitsForTheReadBack()
    {
        std::unique_ptr<RotatorSession> session;
        std::unique_ptr<SimulatorPump> pump;
        QVERIFY(connectPumped(QStringLiteral("sim:?clock=manual&unsolicited=1"), session, pump));
        SetupWizard wizard(session.get());
        wizard.setStartId(SetupWizard::SummaryPageId);
        wizard.show();
        QAbstractButton *finish = wizard.button(QWizard::FinishButton);
        QVERIFY(finish->isVisible());
        QVERIFY(!finish->isEnabled()); // nothing written yet
        auto *note = find<QLabel>(wizard, "finishNote");
        QVERIFY2(note->text().contains(QStringLiteral("reads back")), qPrintable(note->text()));

        QTest::mouseClick(find<QPushButton>(wizard, "write"), Qt::LeftButton);
        QVERIFY(!finish->isEnabled()); // written, not yet read back
        TRY_VERIFY(finish->isEnabled());
        QCOMPARE(find<QListWidget>(wizard, "writeResults")->count(), 2); // the park registers
        QVERIFY2(note->text().contains(QStringLiteral("Every register reads back")), qPrintable(note->text()));
    }

    void noTuningInARehearsalFasterThanRealTime()
    {
        // The simulator on the wall clock, paced to a station clock
        // rehearsing at five times, as the window's Time controller does.
        RotatorSession session;
        session.connectTo(QStringLiteral("sim:?unsolicited=1&start_az=40&start_el=20"));
        TRY_VERIFY_WITH_TIMEOUT(session.capabilities().probed && session.hasPosition(), 5000);
        tracking::StationClock clock;
        tracking::SimulatorPace pace(&session, &clock);
        clock.rehearse(*sky::julianFromIso(QStringLiteral("2018-01-22T07:40:00Z")), 5.0);
        QVERIFY(pace.follows());
        SetupWizard wizard(&session);
        wizard.setStartId(SetupWizard::TuningPageId);
        wizard.show();
        QSignalSpy sent(&session, &RotatorSession::bytesSent);
        auto *status = find<QLabel>(wizard, "tuningStatus");
        QTest::mouseClick(find<QPushButton>(wizard, "tune"), Qt::LeftButton);
        QVERIFY2(status->text().startsWith(QStringLiteral("not tuned: the simulator runs 5 times faster than real "
                                                          "time, with a rehearsal's station clock")),
                 qPrintable(status->text()));
        QVERIFY(find<QPushButton>(wizard, "tune")->isEnabled());
        QVERIFY(!find<QPushButton>(wizard, "accept")->isEnabled()); // no gains offered
        QTest::mouseClick(find<QPushButton>(wizard, "measureSpeed"), Qt::LeftButton);
        QVERIFY2(status->text().startsWith(QStringLiteral("speed not measured: the simulator runs 5 times faster")),
                 qPrintable(status->text()));
        for (const QList<QVariant> &bytes : sent) {
            const QByteArray b = bytes.front().toByteArray();
            QVERIFY2(!b.startsWith("AZ") && !b.startsWith("EL") && !b.startsWith("CR"), b.constData());
        }

        // Back in real time, tuning starts.
        clock.followRealTime();
        QTest::mouseClick(find<QPushButton>(wizard, "tune"), Qt::LeftButton);
        QVERIFY2(!find<QPushButton>(wizard, "tune")->isEnabled(), qPrintable(status->text()));
        wizard.stopRotator();
        TRY_VERIFY(find<QPushButton>(wizard, "tune")->isEnabled());
    }

    void cancellingTheWizardStopsTheRotator()
    {
        RotatorSession session;
        session.connectTo(QStringLiteral("sim:?clock=manual&unsolicited=1&start_az=40&start_el=20"));
        TRY_VERIFY_WITH_TIMEOUT(session.capabilities().probed && session.hasPosition(), 5000);
        SimulatorPump pump;
        sim::Simulator *sim = sim::simulatorBehind(session.link());
        pump.drive(sim);
        SetupWizard wizard(&session);
        wizard.show();
        session.gotoPosition(100, 50);
        TRY_VERIFY_WITH_TIMEOUT(session.azimuth() > 45.0, 5000);
        wizard.reject();
        TRY_VERIFY_WITH_TIMEOUT(sim->rotator().axis(sim::Axis::Azimuth).isStopped(), 5000);
    }
};

QTEST_MAIN(TestSetupWizard)
#include "tst_setupwizard.moc"
