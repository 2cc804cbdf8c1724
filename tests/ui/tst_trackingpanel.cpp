// SPDX-License-Identifier: GPL-3.0-or-later
// The Tracking tab in the operator window: a satellite found by name from
// the element sets, its passes of the next day with the plan each gets on
// this rotator, the pass drawn on the plot, the countdown, and Track / Stop
// tracking, with remote trackers held off while Slew has the rotator. A
// rehearsal clock puts the station on 2018-01-22, eleven seconds before a
// pass of FLOCK 2P-1 over JO65hq, in the element sets' time.

#include "windowfixture.h"

#include "bridge/rotctldserver.h"
#include "polarplotwidget.h"
#include "sky/tlesources.h"
#include "sky/utctime.h"
#include "stopbutton.h"
#include "trackingpanel.h"

#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTest>

using slew::ui::TrackingPanel;

class TrackingPanelTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { WindowFixture::prepareApplication(); }

    void plansTheNextPassesAndTracks()
    {
        WindowFixture f(QStringLiteral("sim:?clock=manual&az_max=450&el_max=180"));
        QVERIFY(f.connectAndWait());
        slew::model::RotatorProfile profile = f.session.profile();
        profile.limits = slew::model::RotatorLimits{0, 450, 0, 180};
        f.session.setProfile(profile);

        // The element sets, from a local file as an operator may list one.
        slew::sky::TleSources *sets = f.window->elementSets();
        sets->setUrls({QUrl::fromLocalFile(QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle"))});
        QSignalSpy loaded(sets, &slew::sky::TleSources::finished);
        sets->refresh();
        QVERIFY(loaded.wait(5000));

        TrackingPanel *panel = f.window->trackingPanel();
        const slew::tracking::StationClock clock(slew::sky::julianFromIso(QStringLiteral("2018-01-22T07:42:45Z")), 1.0);
        panel->setClock(&clock);
        slew::sky::Station station;
        QString error;
        QVERIFY(slew::sky::parseStation(QStringLiteral("JO65hq"), &station, &error));
        panel->setStation(station);
        QVERIFY(panel->selectTarget(QStringLiteral("FLOCK 2P-1")));

        // The day's passes, the first as `slew --passes` gives it, each with its plan.
        QTableWidget *table = panel->passTable();
        QVERIFY2(table->rowCount() >= 6, qPrintable(QString::number(table->rowCount())));
        QCOMPARE(table->item(0, 0)->text(), QStringLiteral("01-22 07:42:56"));
        QCOMPARE(table->item(0, 2)->text(), QStringLiteral("7.1°"));
        QCOMPARE(table->item(0, 5)->text(), QStringLiteral("plain"));
        // A pass over north gets the overlap or the flip on this rotator, never an unwind.
        bool sawOverNorth = false;
        for (int row = 0; row < table->rowCount(); ++row) {
            const QString plan = table->item(row, 5)->text();
            QVERIFY2(!plan.contains(QStringLiteral("unwind")), qPrintable(plan));
            sawOverNorth = sawOverNorth || plan.contains(QStringLiteral("flip")) || plan.contains(QStringLiteral("overlap"));
        }
        QVERIFY(sawOverNorth);

        // The selected pass is on the plot.
        const auto &overlay = f.window->polarPlot()->passOverlay();
        QVERIFY(overlay.has_value());
        QVERIFY(overlay->sky.size() > 400);
        QCOMPARE(overlay->planned.size(), overlay->sky.size());
        QVERIFY2(panel->countdown()->text().startsWith(QStringLiteral("AOS in 0:00:1")), qPrintable(panel->countdown()->text()));

        // Track: the rotator is the tracker's, remote trackers are held off.
        slew::bridge::RotctldServer *server = f.window->rotctldServer();
        QTest::mouseClick(panel->trackButton(), Qt::LeftButton);
        QVERIFY(panel->runner()->isRunning());
        QTRY_VERIFY(panel->runner()->holdsRotator()); // moving to the AOS point
        QVERIFY(server->isRemoteHeld());
        QVERIFY(!panel->trackButton()->isEnabled());

        // Stop tracking hands the rotator back.
        QTest::mouseClick(panel->stopTrackingButton(), Qt::LeftButton);
        QVERIFY(!panel->runner()->isRunning());
        QVERIFY(!server->isRemoteHeld());
        QVERIFY(panel->trackButton()->isEnabled());

        // The window's Stop ends tracking too.
        QTest::mouseClick(panel->trackButton(), Qt::LeftButton);
        QTRY_VERIFY(panel->runner()->holdsRotator());
        QTest::mouseClick(f.window->stopButton(), Qt::LeftButton);
        QVERIFY(!panel->runner()->isRunning());

        // A picture of the tab, for the eye.
        f.window->tabs()->setCurrentWidget(panel);
        f.window->resize(1440, 900);
        f.window->show();
        QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
        QDir().mkpath(QStringLiteral("screenshots"));
        QVERIFY(f.window->grab().save(QStringLiteral("screenshots/tracking-tab.png")));
    }

    void saysWhatIsMissing()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        TrackingPanel *panel = f.window->trackingPanel();
        QSignalSpy messages(panel, &TrackingPanel::message);
        QVERIFY(panel->selectTarget(QStringLiteral("sun")));
        QTest::mouseClick(panel->trackButton(), Qt::LeftButton);
        QVERIFY(!panel->runner()->isRunning());
        QVERIFY(messages.last().at(0).toString().contains(QStringLiteral("station")));
    }
};

QTEST_MAIN(TrackingPanelTest)
#include "tst_trackingpanel.moc"
