// SPDX-License-Identifier: GPL-3.0-or-later
// The Tracking tab in the operator window: a satellite found by name from
// the element sets, its passes of the next day with the plan each gets on
// this rotator, the pass drawn on the plot, the countdown, and Track / Stop
// tracking, with remote trackers held off while Slew has the rotator. A
// rehearsal clock puts the station on 2018-01-22, eleven seconds before a
// pass of FLOCK 2P-1 over JO65hq, in the element sets' time.
//
// Favourites come first in the target list, persist in the settings and
// outlive a reload that lacks them (shown as missing); each element-set
// source says how old its newest elements are, in the warning colour past
// the age limit; and the pointing error is charted while a pass is tracked.

#include "windowfixture.h"

#include "bridge/rotctldserver.h"
#include "tracking/elementsetages.h"
#include "rotor/polarplotwidget.h"
#include "tracking/trackingline.h"
#include "tracking/upcomingpanel.h"
#include "sky/elementsetsources.h"
#include "sky/utctime.h"
#include "stopbutton.h"
#include "tracking/targetpicker.h"
#include "telemetry/telemetrycharts.h"
#include "tracking/trackingpanel.h"

#include <QFile>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTcpSocket>
#include <QThreadPool>
#include <QTest>
#include <QToolButton>
#include <QXYSeries>

using slew::ui::TelemetryRecorder;
using slew::ui::TrackingLine;
using slew::ui::TrackingPanel;
using slew::ui::UpcomingPanel;

namespace {

const QString kAllSets = QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle");

// The rehearsal station, JO65hq, on a clock that starts at `iso`.
void rehearse(TrackingPanel *panel, const slew::tracking::StationClock &clock)
{
    slew::sky::Site station;
    QString error;
    QVERIFY(slew::sky::parseSite(QStringLiteral("JO65hq"), &station, &error));
    // The station's own clock, started where the test's is.
    slew::station::Station *home = panel->station();
    home->clock()->rehearse(clock.nowJulian(), clock.rate());
    home->setPlace(station);
}

// The overlap and flip rotator (450°/180°) on a manual-clock simulator.
const QString kOverlapAndFlip = QStringLiteral("sim:?clock=manual&az_max=450&el_max=180");

bool connectWithOverlapAndFlip(WindowFixture &f)
{
    if (!f.connectAndWait())
        return false;
    slew::model::RotatorProfile profile = f.session.profile();
    profile.limits = slew::model::RotatorLimits{0, 450, 0, 180};
    f.session.setProfile(profile);
    return true;
}

// The pass table is planned off the window's thread: wait for it.
bool passesPlanned(const TrackingPanel *panel)
{
    return QTest::qWaitFor([panel] { return !panel->isPlanning(); }, 10000);
}

QStringList rows(const QListWidget *list)
{
    QStringList texts;
    for (int row = 0; row < list->count(); ++row)
        texts << list->item(row)->text();
    return texts;
}

} // namespace

class TrackingPanelTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { WindowFixture::prepareApplication(); }

    void plansTheNextPassesAndTracks()
    {
        WindowFixture f(kOverlapAndFlip);
        QVERIFY(connectWithOverlapAndFlip(f));
        // The element sets, from a local file as an operator may list one.
        QVERIFY(f.loadElementSets(kAllSets));
        TrackingPanel *panel = f.window->trackingPanel();
        const slew::tracking::StationClock clock(slew::sky::julianFromIso(QStringLiteral("2018-01-22T07:42:45Z")), 1.0);
        rehearse(panel, clock);
        QVERIFY(panel->selectTarget(QStringLiteral("FLOCK 2P-1")));
        QVERIFY(passesPlanned(panel));

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
        // The buttons say what they act on; the line under STOP, that nothing is tracked.
        QCOMPARE(panel->trackButton()->text(), QStringLiteral("Track FLOCK 2P-1"));
        QVERIFY(!panel->stopTrackingButton()->isEnabled());
        QCOMPARE(panel->stopTrackingButton()->toolTip(), QStringLiteral("Nothing is being tracked"));
        QCOMPARE(f.window->trackingLine()->text(), QStringLiteral("Not tracking"));

        // Track: the rotator is the tracker's, remote trackers are held off.
        slew::bridge::RotctldServer *server = f.window->rotctldServer();
        QTest::mouseClick(panel->trackButton(), Qt::LeftButton);
        QVERIFY(panel->runner()->isRunning());
        QTRY_VERIFY(panel->runner()->holdsRotator()); // moving to the AOS point
        QVERIFY(server->isRemoteHeld());
        QVERIFY(!panel->trackButton()->isEnabled());
        QCOMPARE(panel->trackButton()->toolTip(), QStringLiteral("Slew is tracking FLOCK 2P-1: Stop tracking first"));
        QCOMPARE(panel->stopTrackingButton()->text(), QStringLiteral("Stop tracking FLOCK 2P-1"));
        // The line under STOP, with the pass's times from the table: waiting
        // for the AOS, or (past it on a slow machine) tracking until LOS.
        const QString line = f.window->trackingLine()->text();
        const QString los = table->item(0, 3)->text().mid(6);
        QVERIFY2(line.startsWith(QStringLiteral("Next: FLOCK 2P-1, AOS 07:42:56 UTC, in 0:00:"))
                     || line.startsWith(QStringLiteral("Tracking FLOCK 2P-1 until %1 UTC, 0:0").arg(los)),
                 qPrintable(line));

        // Stop tracking hands the rotator back.
        QTest::mouseClick(panel->stopTrackingButton(), Qt::LeftButton);
        QVERIFY(!panel->runner()->isRunning());
        QVERIFY(!server->isRemoteHeld());
        QVERIFY(panel->trackButton()->isEnabled());
        QCOMPARE(f.window->trackingLine()->text(), QStringLiteral("Not tracking"));

        // The window's Stop ends tracking too.
        QTest::mouseClick(panel->trackButton(), Qt::LeftButton);
        QTRY_VERIFY(panel->runner()->holdsRotator());
        QTest::mouseClick(f.window->stopButton(), Qt::LeftButton);
        QVERIFY(!panel->runner()->isRunning());

        // A picture of the tab, for the eye, with the target a favourite.
        QTest::mouseClick(panel->targetPicker()->favouriteButton(), Qt::LeftButton);
        QCOMPARE(panel->targetPicker()->list()->currentItem()->text(), QStringLiteral("★ FLOCK 2P-1"));
        f.window->bringToFront(panel); // the tab: tracking and calibration
        f.window->resize(1440, 900);
        f.window->show();
        QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
        QDir().mkpath(QStringLiteral("screenshots"));
        QVERIFY(f.window->grab().save(QStringLiteral("screenshots/tracking-tab.png")));
        QSettings().remove(QStringLiteral("tracking/favourites"));
    }

    // A pass 0.5° from the zenith on the 450°/180° rotator: the table's
    // badge and the plot say the antenna goes over the top.
    void aZenithPassGoesOverTheTop()
    {
        WindowFixture f(kOverlapAndFlip);
        QVERIFY(connectWithOverlapAndFlip(f));
        QVERIFY(f.loadElementSets(kAllSets));
        TrackingPanel *panel = f.window->trackingPanel();
        const slew::tracking::StationClock clock(slew::sky::julianFromIso(QStringLiteral("2018-01-22T12:10:00Z")), 1.0);
        rehearse(panel, clock);
        QVERIFY(panel->selectTarget(QStringLiteral("03230"))); // an SL-8 rocket body, 89.5° at 12:20:51
        QVERIFY(passesPlanned(panel));
        QTableWidget *table = panel->passTable();
        QVERIFY(table->rowCount() > 0);
        QCOMPARE(table->item(0, 2)->text(), QStringLiteral("89.5°"));
        QCOMPARE(table->item(0, 5)->text(), QStringLiteral("over the top"));
        const auto &overlay = f.window->polarPlot()->passOverlay();
        QVERIFY(overlay.has_value());
        QVERIFY(overlay->overTheTop);

        f.window->bringToFront(panel);
        f.window->resize(1440, 900);
        f.window->show();
        QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
        QDir().mkpath(QStringLiteral("screenshots"));
        QVERIFY(f.window->grab().save(QStringLiteral("screenshots/tracking-over-the-top.png")));
    }

    // The same pass on a 360°/90° rotator: no way over the top, so the
    // table says before AOS how far it will lag, and the plot shows the
    // planned path cutting the corner near the zenith, the swing started
    // early, rather than chasing the sky's bearing round.
    void aZenithPassOnAQuarterTurnElevationLagsAndSaysSo()
    {
        WindowFixture f(QStringLiteral("sim:?clock=manual"));
        QVERIFY(f.connectAndWait());
        QCOMPARE(f.session.profile().limits.elMax, 90.0);
        QVERIFY(f.loadElementSets(kAllSets));
        TrackingPanel *panel = f.window->trackingPanel();
        const slew::tracking::StationClock clock(slew::sky::julianFromIso(QStringLiteral("2018-01-22T12:10:00Z")), 1.0);
        rehearse(panel, clock);
        QVERIFY(panel->selectTarget(QStringLiteral("03230")));
        QVERIFY(passesPlanned(panel));
        QTableWidget *table = panel->passTable();
        QVERIFY(table->rowCount() > 0);
        QCOMPARE(table->item(0, 2)->text(), QStringLiteral("89.5°"));
        const QString plan = table->item(0, 5)->text();
        QVERIFY2(plan.startsWith(QStringLiteral("lags")), qPrintable(plan)); // plain: no flip, no overlap
        // The least-worst swing: a G-5500 cannot do better than about 3.3°
        // on this pass; chasing the bearing would be 5.7° and more.
        const double lag = plan.section(QStringLiteral("lags "), 1).section(QChar(0xB0), 0, 0).toDouble();
        QVERIFY2(lag > 3.0 && lag < 4.0, qPrintable(plan));
        const auto &overlay = f.window->polarPlot()->passOverlay();
        QVERIFY(overlay.has_value());
        QVERIFY(!overlay->overTheTop && !overlay->flipped);
        // Near the top the planned azimuth parts from the sky's (the swing
        // taken early and ended late), and the planned elevation is never
        // below the sky's there: high up, an azimuth offset costs little.
        QCOMPARE(overlay->planned.size(), overlay->sky.size());
        double widest = 0;
        for (int i = 0; i < overlay->sky.size(); ++i) {
            const QPointF sky = overlay->sky[i], planned = overlay->planned[i];
            const double apart = std::abs(std::remainder(planned.x() - sky.x(), 360.0));
            widest = std::max(widest, apart);
            if (apart > 1.0)
                QVERIFY2(planned.y() >= sky.y() - 0.05, qPrintable(QStringLiteral("%1 below %2").arg(planned.y()).arg(sky.y())));
        }
        QVERIFY2(widest > 20.0, qPrintable(QString::number(widest)));

        f.window->bringToFront(panel);
        f.window->resize(1440, 900);
        f.window->show();
        QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
        QDir().mkpath(QStringLiteral("screenshots"));
        QVERIFY(f.window->grab().save(QStringLiteral("screenshots/tracking-zenith-swing.png")));
    }

    // Choosing a target plans its passes on a worker thread: the window
    // goes on, says it is planning, and a plan for an earlier choice that
    // arrives late is dropped.
    void planningDoesNotHoldTheWindow()
    {
        WindowFixture f(kOverlapAndFlip);
        QVERIFY(connectWithOverlapAndFlip(f));
        QVERIFY(f.loadElementSets(kAllSets));
        TrackingPanel *panel = f.window->trackingPanel();
        const slew::tracking::StationClock clock(slew::sky::julianFromIso(QStringLiteral("2018-01-22T07:42:45Z")), 1.0);
        rehearse(panel, clock);
        QVERIFY(passesPlanned(panel));

        QElapsedTimer took;
        took.start();
        QVERIFY(panel->selectTarget(QStringLiteral("moon"))); // the slowest to plan
        qInfo("choosing the moon held the window for %lld ms", took.elapsed());
        QVERIFY(panel->isPlanning());
        QCOMPARE(panel->countdown()->text(), QStringLiteral("planning the passes…"));
        QCOMPARE(panel->passTable()->rowCount(), 0);

        QVERIFY(panel->selectTarget(QStringLiteral("FLOCK 2P-1")));
        QVERIFY(passesPlanned(panel));
        // Let the moon's forecast finish and its result arrive: it is not shown.
        QSignalSpy shown(panel, &TrackingPanel::passesShown);
        QVERIFY(QTest::qWaitFor([] { return QThreadPool::globalInstance()->activeThreadCount() == 0; }, 10000));
        QCoreApplication::processEvents();
        QCOMPARE(shown.count(), 0);
        QCOMPARE(panel->passTable()->item(0, 0)->text(), QStringLiteral("01-22 07:42:56"));
        QVERIFY(panel->countdown()->text().startsWith(QStringLiteral("AOS in")));
    }

    void favouritesComeFirstPersistAndOutliveAReload()
    {
        QTemporaryDir dir;
        // Two other satellites: a reload that lacks FLOCK 2P-1.
        const QString others = dir.filePath(QStringLiteral("others.tle"));
        {
            QFile all(kAllSets), out(others);
            QVERIFY(all.open(QIODevice::ReadOnly) && out.open(QIODevice::WriteOnly));
            const QList<QByteArray> lines = all.readAll().split('\n');
            for (int i = 9; i < 15; ++i) // after the header and FLOCK 2P-1's three lines
                out.write(lines[i] + '\n');
        }
        {
            WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
            TrackingPanel *panel = f.window->trackingPanel();
            QVERIFY(f.loadElementSets(kAllSets));
            QVERIFY(panel->selectTarget(QStringLiteral("FLOCK 2P-1")));
            QCOMPARE(panel->targetPicker()->favouriteButton()->text(), QStringLiteral("☆"));
            QTest::mouseClick(panel->targetPicker()->favouriteButton(), Qt::LeftButton);
            QVERIFY(panel->targetPicker()->favouriteButton()->isChecked());
            QCOMPARE(panel->targetPicker()->favouriteButton()->text(), QStringLiteral("★"));
            QVERIFY(panel->selectTarget(QStringLiteral("moon")));
            QTest::mouseClick(panel->targetPicker()->favouriteButton(), Qt::LeftButton);

            // With no search, the favourites head the list, in the order marked.
            QVERIFY(panel->selectTarget(QString()));
            QStringList listed = rows(panel->targetPicker()->list());
            QCOMPARE(listed.mid(0, 3), (QStringList{QStringLiteral("★ FLOCK 2P-1"), QStringLiteral("★ Moon"), QStringLiteral("Sun")}));
            QCOMPARE(listed.count(QStringLiteral("FLOCK 2P-1")), 0); // listed once
            QCOMPARE(QSettings().value(QStringLiteral("tracking/favourites")).toStringList(),
                     (QStringList{QStringLiteral("41617 FLOCK 2P-1"), QStringLiteral("moon")}));
            // The station only now: the moon's passes take long to plan.
            const slew::tracking::StationClock clock(slew::sky::julianFromIso(QStringLiteral("2018-01-22T07:42:45Z")), 1.0);
            rehearse(panel, clock);
            QVERIFY(passesPlanned(panel));
            QVERIFY(panel->passTable()->rowCount() > 0);
            QTest::mouseClick(panel->targetPicker()->favouritesOnlyButton(), Qt::LeftButton);
            QCOMPARE(panel->targetPicker()->list()->count(), 2);
            QCOMPARE(panel->targetPicker()->list()->currentRow(), 0);
            QVERIFY(passesPlanned(panel));
            QVERIFY(panel->passTable()->rowCount() > 0);

            // A reload without it: still listed, as missing, and nothing to plan.
            QVERIFY(f.loadElementSets(others));
            listed = rows(panel->targetPicker()->list());
            QCOMPARE(listed.size(), 2);
            QCOMPARE(listed[0], QStringLiteral("★ FLOCK 2P-1 (41617): not in the loaded element sets"));
            panel->targetPicker()->list()->setCurrentRow(0);
            QCOMPARE(panel->passTable()->rowCount(), 0);
            QCOMPARE(panel->countdown()->text(), QStringLiteral("not in the loaded element sets"));
            QVERIFY(panel->targetPicker()->favouriteButton()->isChecked()); // and can be unmarked from here
        }

        // Another run of Slew: the favourites are read back; the sets come
        // back with the source, and with them the satellite.
        WindowFixture g(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        TrackingPanel *panel = g.window->trackingPanel();
        QCOMPARE(rows(panel->targetPicker()->list()).mid(0, 2),
                 (QStringList{QStringLiteral("★ FLOCK 2P-1 (41617): not in the loaded element sets"), QStringLiteral("★ Moon")}));
        QVERIFY(g.loadElementSets(kAllSets));
        QCOMPARE(panel->targetPicker()->list()->item(0)->text(), QStringLiteral("★ FLOCK 2P-1"));

        // Unmarked with the star: gone from the favourites and the settings.
        panel->targetPicker()->list()->setCurrentRow(0);
        QTest::mouseClick(panel->targetPicker()->favouriteButton(), Qt::LeftButton);
        QVERIFY(!panel->targetPicker()->favouriteButton()->isChecked());
        QCOMPARE(panel->targetPicker()->list()->item(0)->text(), QStringLiteral("★ Moon"));
        QCOMPARE(QSettings().value(QStringLiteral("tracking/favourites")).toStringList(), QStringList{QStringLiteral("moon")});
        QSettings().remove(QStringLiteral("tracking/favourites"));
    }

    void eachSourceSaysHowOldItsElementsAre()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        TrackingPanel *panel = f.window->trackingPanel();
        slew::ui::ElementSetAges *ages = panel->elementSetAges();
        QCOMPARE(ages->lines().size(), 1);
        QVERIFY2(ages->lines()[0]->text().startsWith(QStringLiteral("none loaded")), qPrintable(ages->lines()[0]->text()));

        QVERIFY(f.loadElementSets(kAllSets));
        // The newest set is from 2018-01-22 01:04:49 UTC: fresh on the morning of the pass.
        const slew::tracking::StationClock morning(slew::sky::julianFromIso(QStringLiteral("2018-01-22T07:42:45Z")), 1.0);
        rehearse(panel, morning);
        QLabel *line = ages->lines()[0];
        QVERIFY2(line->text().startsWith(QStringLiteral("gpredict-satellites-2018.tle: 979 set(s), newest elements 6.6 h old, downloaded ")),
                 qPrintable(line->text()));
        QVERIFY(!slew::ui::ElementSetAges::isStale(line));

        // Three weeks later the same sets are past the 14-day limit: a
        // warning, and One target refuses them as the schedule drops them.
        const slew::tracking::StationClock later(slew::sky::julianFromIso(QStringLiteral("2018-02-15T01:04:49Z")), 1.0);
        rehearse(panel, later);
        QVERIFY2(line->text().contains(QStringLiteral("newest elements 24.0 days old")), qPrintable(line->text()));
        QVERIFY2(line->text().contains(QStringLiteral("older than 14 days, not tracked")), qPrintable(line->text()));
        QVERIFY(slew::ui::ElementSetAges::isStale(line));
        QVERIFY(!line->styleSheet().isEmpty());

        QVERIFY(f.connectAndWait());
        QVERIFY(panel->selectTarget(QStringLiteral("FLOCK 2P-1")));
        QVERIFY2(panel->trackButton()->toolTip().startsWith(
                     QStringLiteral("To track: refresh the element sets, or raise the limit under Sky → Element sets… "
                                    "(its elements are 25.1 days from now (epoch 2018-01-20T22:08:")),
                 qPrintable(panel->trackButton()->toolTip()));
        QSignalSpy messages(panel, &TrackingPanel::message);
        QTest::mouseClick(panel->trackButton(), Qt::LeftButton);
        QVERIFY(!panel->runner()->isRunning());
        QVERIFY2(messages.last().at(0).toString().startsWith(
                     QStringLiteral("FLOCK 2P-1 is not tracked: its elements are 25.1 days from now")),
                 qPrintable(messages.last().at(0).toString()));

        // The operator's limit (Sky → Element sets…, kept in the settings)
        // reaches the station: a month, and the same sets are tracked.
        panel->station()->setElementAgeLimitDays(30);
        rehearse(panel, later);
        QVERIFY(!slew::ui::ElementSetAges::isStale(line));
        QVERIFY2(panel->trackButton()->toolTip().startsWith(QStringLiteral("Track every pass")),
                 qPrintable(panel->trackButton()->toolTip()));
        QTest::mouseClick(panel->trackButton(), Qt::LeftButton);
        QVERIFY(panel->runner()->isRunning());
        panel->station()->untrack(QStringLiteral("done"));
    }

    void chartsThePointingErrorWhileTracking()
    {
        WindowFixture f(kOverlapAndFlip);
        QVERIFY(connectWithOverlapAndFlip(f));
        QVERIFY(f.loadElementSets(kAllSets));
        TrackingPanel *panel = f.window->trackingPanel();
        // A minute into the pass: tracking starts at once.
        const slew::tracking::StationClock clock(slew::sky::julianFromIso(QStringLiteral("2018-01-22T07:44:00Z")), 1.0);
        rehearse(panel, clock);
        QVERIFY(panel->selectTarget(QStringLiteral("FLOCK 2P-1")));

        slew::ui::TelemetryCharts *charts = f.window->telemetryCharts();
        QXYSeries *pointing = charts->series(TelemetryRecorder::PointingError);
        QVERIFY(pointing);
        auto plotted = [&] {
            charts->redraw();
            return pointing->count();
        };
        QCOMPARE(plotted(), 0); // positions, but nothing tracked yet
        QVERIFY(charts->findChild<QWidget *>(QStringLiteral("chartPointing"))->isHidden());

        QTest::mouseClick(panel->trackButton(), Qt::LeftButton);
        TRY_VERIFY(panel->runner()->tracker().state() == slew::tracking::Tracker::State::Tracking);
        TRY_VERIFY(plotted() > 10);
        QVERIFY(!charts->findChild<QWidget *>(QStringLiteral("chartPointing"))->isHidden());
        for (const QPointF &p : pointing->points())
            QVERIFY2(p.y() >= 0.0 && p.y() < 180.0, qPrintable(QString::number(p.y())));

        // Stopped: positions go on, the pointing error does not.
        QTest::mouseClick(panel->stopTrackingButton(), Qt::LeftButton);
        const int afterStop = plotted();
        int positions = 0;
        QObject::connect(&f.session, &slew::session::RotatorSession::positionChanged, panel, [&] { ++positions; });
        TRY_VERIFY(positions > 20);
        QCOMPARE(plotted(), afterStop);

        f.window->bringToFront(charts);
        QDir().mkpath(QStringLiteral("screenshots"));
        QVERIFY(f.window->grab().save(QStringLiteral("screenshots/telemetry-pointing-error.png")));
    }

    void aPassUnderWayShowsWhereItRose()
    {
        // FLOCK 2P-1 rose at 07:42:56 (the pass above); looked at 90 s
        // later, the table shows that AOS, marked, not "now".
        WindowFixture f;
        QVERIFY(f.loadElementSets(kAllSets));
        TrackingPanel *panel = f.window->trackingPanel();
        const slew::tracking::StationClock clock(slew::sky::julianFromIso(QStringLiteral("2018-01-22T07:44:26Z")), 1.0);
        rehearse(panel, clock);
        QVERIFY(panel->selectTarget(QStringLiteral("FLOCK 2P-1")));
        QVERIFY(passesPlanned(panel));
        QTableWidget *table = panel->passTable();
        QVERIFY(table->rowCount() >= 2);
        QCOMPARE(table->item(0, 0)->text(), QStringLiteral("01-22 07:42:56 (under way)"));
        QCOMPARE(table->item(0, 2)->text(), QStringLiteral("7.1°"));
        QVERIFY(!table->item(1, 0)->text().contains(QStringLiteral("under way")));
        // The pass on the plot is what is left of it.
        const auto &overlay = f.window->polarPlot()->passOverlay();
        QVERIFY(overlay.has_value() && !overlay->sky.isEmpty());
    }

    void satellitesFoundByTheNamesOperatorsUse()
    {
        // One target's search, as the Schedule's and --passes: AMSAT names,
        // designations in parentheses, a catalogue number; a favourite too.
        WindowFixture f;
        QVERIFY(f.loadElementSets(kAllSets));
        TrackingPanel *panel = f.window->trackingPanel();
        auto *picker = panel->findChild<slew::ui::TargetPicker *>(QStringLiteral("targetPicker"));
        QVERIFY(picker);
        for (const auto &[query, number] : {std::pair{"AO-91", 43017}, std::pair{"SO-50", 27607}, std::pair{"FO-29", 24278},
                                             std::pair{"ZARYA", 25544}, std::pair{"oscar 7", 7530}, std::pair{"43137", 43137}}) {
            QVERIFY2(panel->selectTarget(QString::fromLatin1(query)), query);
            const std::optional<slew::sky::FavouriteTarget> chosen = picker->chosen();
            QVERIFY2(chosen && chosen->catalogueNumber == number, query);
        }
        auto *favourite = panel->findChild<QToolButton *>(QStringLiteral("favouriteToggle"));
        QVERIFY(favourite);
        QVERIFY(panel->selectTarget(QStringLiteral("AO-91")));
        QVERIFY(!favourite->isChecked());
        favourite->click(); // now a favourite: listed first, and still found
        QVERIFY(panel->selectTarget(QStringLiteral("AO-91")));
        QCOMPARE(picker->chosen()->catalogueNumber, 43017);
        favourite->click();
    }

    void directionsTypedInTheSearch()
    {
        // A fixed direction and a radio source are targets too: typed in
        // full, planned like a pass, drawn on the plot, tracked.
        WindowFixture f(kOverlapAndFlip);
        QVERIFY(connectWithOverlapAndFlip(f));
        TrackingPanel *panel = f.window->trackingPanel();
        const slew::tracking::StationClock clock(slew::sky::julianFromIso(QStringLiteral("2026-11-23T18:00:00Z")), 1.0);
        rehearse(panel, clock);
        QVERIFY(panel->selectTarget(QStringLiteral("azel:200,30")));
        QVERIFY(passesPlanned(panel));
        QCOMPARE(panel->passTable()->rowCount(), 1); // held for the whole look-ahead
        QCOMPARE(panel->passTable()->item(0, 2)->text(), QStringLiteral("30.0°"));
        QTest::mouseClick(panel->trackButton(), Qt::LeftButton);
        QVERIFY(panel->runner()->isRunning());
        QVERIFY(f.waitUntilAt(200, 30, 0.5, 30000));

        // Cassiopeia A never sets at JO65: one pass through the whole day.
        QTest::mouseClick(panel->findChild<QPushButton *>(QStringLiteral("stopTracking")), Qt::LeftButton);
        QVERIFY(panel->selectTarget(QStringLiteral("radec:23:23:24,+58:48:54")));
        QVERIFY(passesPlanned(panel));
        QVERIFY(panel->passTable()->rowCount() >= 1);
        const auto &overlay = f.window->polarPlot()->passOverlay();
        QVERIFY(overlay.has_value() && overlay->sky.size() > 100);
        QVERIFY2(panel->findChild<QLabel *>(QStringLiteral("trackingLive"))->text().startsWith(QStringLiteral("az ")),
                 qPrintable(panel->findChild<QLabel *>(QStringLiteral("trackingLive"))->text()));
        // A direction that does not read is no target.
        QVERIFY(!panel->selectTarget(QStringLiteral("azel:400,10")));
    }

    void waitsWhileARemoteTrackerSteers()
    {
        // The reverse of holding remote trackers off: while Gpredict (here a
        // raw rotctld client) steers, Track is refused and says who steers.
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        TrackingPanel *panel = f.window->trackingPanel();
        const slew::tracking::StationClock clock(slew::sky::julianFromIso(QStringLiteral("2026-11-23T18:00:00Z")), 1.0);
        rehearse(panel, clock);
        QVERIFY(panel->selectTarget(QStringLiteral("azel:100,20")));
        slew::bridge::RotctldServer *server = f.window->rotctldServer();
        QString error;
        QVERIFY2(server->listen(QHostAddress::LocalHost, 0, &error), qPrintable(error));
        QTcpSocket gpredict;
        gpredict.connectToHost(QHostAddress::LocalHost, server->port());
        QTRY_COMPARE(gpredict.state(), QAbstractSocket::ConnectedState);
        QSignalSpy answered(&gpredict, &QTcpSocket::readyRead);
        gpredict.write("P 30 10\n");
        QVERIFY(answered.wait(5000));
        QCOMPARE(gpredict.readAll(), QByteArray("RPRT 0\n"));
        QSignalSpy messages(panel, &TrackingPanel::message);
        QTest::mouseClick(panel->trackButton(), Qt::LeftButton);
        QVERIFY(!panel->runner()->isRunning());
        QVERIFY2(messages.last().at(0).toString().contains(QStringLiteral("is steering the rotator")),
                 qPrintable(messages.last().at(0).toString()));
        QVERIFY(server->remoteSteering().startsWith(QStringLiteral("127.0.0.1:")));
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
        // The button says what it would track, and what is missing for it.
        QCOMPARE(panel->trackButton()->text(), QStringLiteral("Track the sun"));
        QCOMPARE(panel->trackButton()->toolTip(),
                 QStringLiteral("To track: set the station (Sky → Station…); connect a rotator"));
    }

    void upcomingListsTheFavouritesNextPasses()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        QVERIFY(f.loadElementSets(kAllSets));
        TrackingPanel *panel = f.window->trackingPanel();
        UpcomingPanel *upcoming = f.window->upcomingPanel();
        const auto planned = [upcoming] { return QTest::qWaitFor([upcoming] { return !upcoming->isPlanning(); }, 10000); };
        const auto status = [upcoming] { return upcoming->findChild<QLabel *>(QStringLiteral("upcomingStatus"))->text(); };
        QVERIFY(planned());
        QVERIFY2(status().contains(QStringLiteral("Set the station")), qPrintable(status()));
        const slew::tracking::StationClock clock(slew::sky::julianFromIso(QStringLiteral("2018-01-22T07:42:45Z")), 1.0);
        rehearse(panel, clock);
        QVERIFY(planned());
        QCOMPARE(upcoming->table()->rowCount(), 0); // no favourites yet: it says how to get some
        QVERIFY2(status().contains(QStringLiteral("Star ")), qPrintable(status()));

        // Two favourites, starred in One target.
        QVERIFY(panel->selectTarget(QStringLiteral("FLOCK 2P-1")));
        QVERIFY(passesPlanned(panel));
        const QList<slew::sky::Pass> flockPasses = panel->passes();
        QTest::mouseClick(panel->targetPicker()->favouriteButton(), Qt::LeftButton);
        QVERIFY(panel->selectTarget(QStringLiteral("sun")));
        QTest::mouseClick(panel->targetPicker()->favouriteButton(), Qt::LeftButton);
        QVERIFY(planned());

        // Soonest first, each pass as One target plans it, with its countdown.
        const QList<UpcomingPanel::Row> &rows = upcoming->rows();
        QVERIFY(rows.size() >= flockPasses.size() + 1);
        for (int i = 1; i < rows.size(); ++i)
            QVERIFY(rows.at(i - 1).planned.pass.aos.julian <= rows.at(i).planned.pass.aos.julian);
        QTableWidget *table = upcoming->table();
        const auto firstRowOf = [table](const QString &name) {
            for (int row = 0; row < table->rowCount(); ++row)
                if (table->item(row, 0)->text() == name)
                    return row;
            return -1;
        };
        const int flockRow = firstRowOf(QStringLiteral("FLOCK 2P-1")), sunRow = firstRowOf(QStringLiteral("the sun"));
        QVERIFY(flockRow >= 0 && sunRow >= 0);
        QCOMPARE(table->item(flockRow, 1)->text(), QStringLiteral("01-22 07:42:56"));
        QVERIFY2(table->item(flockRow, 2)->text().startsWith(QStringLiteral("0:00:")), qPrintable(table->item(flockRow, 2)->text()));
        QCOMPARE(table->item(flockRow, 3)->text(), QStringLiteral("7.1°"));
        QCOMPARE(table->item(flockRow, 5)->text(), QStringLiteral("plain"));
        QList<double> flockAos, sunAos;
        for (const UpcomingPanel::Row &r : rows)
            (r.target == QStringLiteral("the sun") ? sunAos : flockAos) << r.planned.pass.aos.julian;
        QCOMPARE(flockAos.size(), flockPasses.size());
        for (int i = 0; i < flockAos.size(); ++i)
            QCOMPARE(flockAos.at(i), flockPasses.at(i).aos.julian);
        QVERIFY(!sunAos.isEmpty());

        // A double click opens the pass's target in One target.
        QVERIFY(panel->selectTarget(QStringLiteral("FLOCK 2P-1")));
        emit table->cellDoubleClicked(sunRow, 0);
        QCOMPARE(panel->targetPicker()->chosen()->kind, slew::sky::FavouriteTarget::Kind::Sun);
        QVERIFY(panel->isVisibleTo(f.window.get()));
        QSettings().remove(QStringLiteral("tracking/favourites"));
    }

    void theLineUnderStopSaysWhatIsTracked()
    {
        // Each phase of the station's tracking, as the line words it, at
        // 2018-01-22 07:40:00 UTC for a pass 07:42:56-07:51:04.
        using slew::face::TrackingNow;
        const double now = *slew::sky::julianFromIso(QStringLiteral("2018-01-22T07:40:00Z"));
        TrackingNow followed;
        QCOMPARE(TrackingLine::textFor(followed, now), QStringLiteral("Not tracking"));
        followed.target = QStringLiteral("FLOCK 2P-1");
        followed.phase = TrackingNow::Phase::Planning;
        QCOMPARE(TrackingLine::textFor(followed, now), QStringLiteral("FLOCK 2P-1: finding the next pass"));
        slew::sky::Pass pass;
        pass.aos.julian = *slew::sky::julianFromIso(QStringLiteral("2018-01-22T07:42:56Z"));
        pass.los.julian = *slew::sky::julianFromIso(QStringLiteral("2018-01-22T07:51:04Z"));
        followed.pass = pass;
        followed.phase = TrackingNow::Phase::Waiting;
        QCOMPARE(TrackingLine::textFor(followed, now), QStringLiteral("Next: FLOCK 2P-1, AOS 07:42:56 UTC, in 0:02:56"));
        QCOMPARE(TrackingLine::textFor(followed, pass.aos.julian + 1.0 / 86400),
                 QStringLiteral("FLOCK 2P-1: the antenna is on its way, LOS 07:51:04 UTC"));
        followed.phase = TrackingNow::Phase::Tracking;
        QCOMPARE(TrackingLine::textFor(followed, pass.aos.julian + 60.0 / 86400),
                 QStringLiteral("Tracking FLOCK 2P-1 until 07:51:04 UTC, 0:07:08 left"));
        followed.phase = TrackingNow::Phase::Done;
        QCOMPARE(TrackingLine::textFor(followed, pass.los.julian), QStringLiteral("FLOCK 2P-1: pass ended, finding the next"));
        followed.phase = TrackingNow::Phase::Tracking;
        followed.pass.reset();
        followed.target = QStringLiteral("az 200.0°, el 40.0°");
        QCOMPARE(TrackingLine::textFor(followed, now), QStringLiteral("Tracking az 200.0°, el 40.0°"));
    }
};

QTEST_MAIN(TrackingPanelTest)
#include "tst_trackingpanel.moc"
