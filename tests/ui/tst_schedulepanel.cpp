// SPDX-License-Identifier: GPL-3.0-or-later
// The Schedule tab in a real X11 window (Xvfb, xcb): targets added by name,
// refused when they name nothing or are listed already, a preview of the
// next 24 hours with every pass's decision, a drag to the top that changes
// who wins an overlap, the list kept for the next start, Run and Stop on the
// built-in simulator, and the tab whole at 1280x720. The station's horizon
// mask, set in Sky → Station…, is drawn on the plot.

#include "layoutfaults.h"
#include "windowfixture.h"

#include "linkschemes.h"
#include "operatortheme.h"
#include "rotor/polarplotwidget.h"
#include "tracking/schedulepanel.h"
#include "tracking/scheduletimeline.h"
#include "sky/horizonmask.h"
#include "sky/elementsetsources.h"
#include "sky/utctime.h"
#include "station/schedulerunner.h"
#include "tracking/stationdialog.h"

#include <QApplication>
#include <QDialogButtonBox>
#include <QDir>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

using slew::schedule::DropReason;
using slew::schedule::ScheduledPass;
using slew::ui::SchedulePanel;

namespace {

const QString kAllSets = QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle");

SchedulePanel *scheduleTab(WindowFixture &f)
{
    SchedulePanel *panel = f.window->schedulePanel();
    f.window->bringToFront(panel);
    return panel;
}

const ScheduledPass *passOf(const slew::schedule::Schedule &plan, const QString &target, const char *iso)
{
    const double julian = *slew::sky::julianFromIso(QString::fromLatin1(iso));
    for (const ScheduledPass &p : plan.passes)
        if (p.target == target && p.startJulian <= julian && p.endJulian >= julian)
            return &p;
    return nullptr;
}

bool waitForPreview(SchedulePanel *panel)
{
    QSignalSpy shown(panel, &SchedulePanel::previewShown);
    return shown.wait(20000);
}

// Adds as the Add field does and waits for the station's word: the spec
// listed, or empty with the refusal.
QString add(SchedulePanel *panel, const QString &text, QString *refusal = nullptr)
{
    QSignalSpy added(panel, &SchedulePanel::targetAdded);
    QSignalSpy refused(panel, &SchedulePanel::targetRefused);
    if (panel->addTarget(text)) {
        if (!added.wait(20000) && refused.isEmpty())
            return {};
    }
    if (!refused.isEmpty()) {
        if (refusal)
            *refusal = refused.first().first().toString();
        return {};
    }
    return added.isEmpty() ? QString() : added.first().first().toString();
}

} // namespace

class SchedulePanelTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QCOMPARE(QGuiApplication::platformName(), QStringLiteral("xcb"));
        WindowFixture::prepareApplication();
        slew::registerLinkSchemes();
        slew::ui::applyOperatorTheme(*qobject_cast<QApplication *>(QCoreApplication::instance()));
    }

    void init()
    {
        QSettings().remove(QStringLiteral("schedule"));
        QSettings().remove(QStringLiteral("sky"));
    }

    void previewsPriorityAndKeepsTheList()
    {
        {
            WindowFixture f;
            f.window->resize(1280, 720);
            QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
            QVERIFY(f.loadElementSets(kAllSets));
            QVERIFY(f.rehearseAt(QStringLiteral("2018-01-22T09:00:00Z"), 1.0));
            SchedulePanel *panel = scheduleTab(f);
            // A page of the Tracking tab, beside One target.
            QCOMPARE(f.window->tabs()->tabText(f.window->tabs()->currentIndex()), QStringLiteral("Tracking"));
            QVERIFY(panel->isVisible());
            // No target yet: the empty time line is headed with today.
            QCOMPARE(panel->timeline()->dayText(), QStringLiteral("UTC, 22 Jan"));

            QCOMPARE(add(panel, QStringLiteral("FLOCK 2P-1")), QStringLiteral("41617"));
            QCOMPARE(add(panel, QStringLiteral("ENVISAT")), QStringLiteral("27386"));
            // Two added at once, before the station has named the first.
            QSignalSpy added(panel, &SchedulePanel::targetAdded);
            QVERIFY(panel->addTarget(QStringLiteral("perseus-m1")));
            QVERIFY(panel->addTarget(QStringLiteral("sun")));
            QVERIFY(waitForPreview(panel));
            QCOMPARE(added.size(), 2);
            QCOMPARE(panel->targetSpecs(), (QStringList{"41617", "27386", "40039", "sun"}));
            auto *list = f.find<QListWidget>(QStringLiteral("scheduleTargets"));
            QCOMPARE(list->item(2)->text(), QStringLiteral("PERSEUS-M1"));
            // Refused, each saying why, and the list as it was.
            QString refusal;
            QCOMPARE(add(panel, QStringLiteral("NO SUCH SATELLITE"), &refusal), QString());
            QVERIFY2(refusal.contains(QStringLiteral("NO SUCH SATELLITE")), qPrintable(refusal));
            QVERIFY(f.find<QLabel>(QStringLiteral("scheduleRefusal"))->isVisible());
            QVERIFY(!panel->addTarget(QStringLiteral("41617")));
            QVERIFY2(f.find<QLabel>(QStringLiteral("scheduleRefusal"))->text().contains("in the list already"),
                     qPrintable(f.find<QLabel>(QStringLiteral("scheduleRefusal"))->text()));
            // The same satellite by another name: found, then refused.
            QCOMPARE(add(panel, QStringLiteral("envisat"), &refusal), QString());
            QCOMPARE(refusal, QStringLiteral("ENVISAT is in the list already: a target has one priority"));
            QCOMPARE(add(panel, QStringLiteral("azel:400,10"), &refusal), QString());
            QVERIFY2(!refusal.isEmpty(), "an azimuth out of range");
            QCOMPARE(panel->targetSpecs().size(), 4);
            // The sun leaves again, as the Remove button does.
            list->setCurrentRow(3);
            f.find<QPushButton>(QStringLiteral("scheduleRemove"))->click();
            QVERIFY(waitForPreview(panel));
            QCOMPARE(panel->targetSpecs().size(), 3);

            // FLOCK's pass of 09:15:45 wins the overlap with ENVISAT's.
            const ScheduledPass *flock = passOf(panel->shownSchedule(), "FLOCK 2P-1", "2018-01-22T09:20:00Z");
            const ScheduledPass *envisat = passOf(panel->shownSchedule(), "ENVISAT", "2018-01-22T09:30:00Z");
            QVERIFY(flock && envisat);
            QVERIFY(flock->taken);
            QCOMPARE(envisat->reason, DropReason::Overlap);
            QVERIFY(!panel->timeline()->barFor(*envisat).isEmpty());
            auto *table = f.find<QTableWidget>(QStringLiteral("schedulePasses"));
            bool listed = false;
            for (int row = 0; row < table->rowCount(); ++row)
                listed |= table->item(row, 1)->text() == QStringLiteral("ENVISAT [2]")
                          && table->item(row, 3)->text().startsWith(QStringLiteral("dropped: overlaps FLOCK 2P-1"));
            QVERIFY(listed);
            QVERIFY(f.find<QLabel>(QStringLiteral("scheduleState"))->text().startsWith(QStringLiteral("Preview: ")));

            // Dragged to the top, ENVISAT wins instead.
            QVERIFY(list->model()->moveRow(QModelIndex(), 1, QModelIndex(), 0));
            QVERIFY(waitForPreview(panel));
            envisat = passOf(panel->shownSchedule(), "ENVISAT", "2018-01-22T09:30:00Z");
            flock = passOf(panel->shownSchedule(), "FLOCK 2P-1", "2018-01-22T09:20:00Z");
            QVERIFY(envisat && flock);
            QVERIFY(envisat->taken);
            QCOMPARE(flock->reason, DropReason::Overlap);

            // The tab whole at 1280x720, the time line and the table filled.
            const QString faults = layoutFaults(f.window.get()).join(QLatin1Char('\n'));
            QVERIFY2(faults.isEmpty(), qPrintable(faults));
            QDir().mkpath(QStringLiteral("screenshots"));
            QVERIFY(f.window->grab().save(QStringLiteral("screenshots/schedule-tab.png")));
        }
        // The list, in its order, at the next start; named by the sets once
        // they have come in.
        WindowFixture f;
        auto *list = f.find<QListWidget>(QStringLiteral("scheduleTargets"));
        SchedulePanel *panel = scheduleTab(f);
        QVERIFY(f.loadElementSets(kAllSets));
        QCOMPARE(panel->targetSpecs(), (QStringList{"27386", "41617", "40039"}));
        QTRY_COMPARE(list->item(0)->text(), QStringLiteral("ENVISAT"));
        // Added by the names operators use.
        for (const char *name : {"AO-91", "SO-50", "FO-29", "ZARYA"})
            QVERIFY2(!add(panel, QString::fromLatin1(name)).isEmpty(), name);
        QCOMPARE(panel->targetSpecs().mid(3), (QStringList{"43017", "27607", "24278", "25544"}));
        // Removed again, as the Remove button does, so the next test starts
        // from the three.
        auto *remove = f.find<QPushButton>(QStringLiteral("scheduleRemove"));
        while (list->count() > 3) {
            list->setCurrentRow(3);
            remove->click();
        }
        QCOMPARE(panel->targetSpecs().size(), 3);
    }

    void runsAndStopsOnTheSimulator()
    {
        WindowFixture f;
        f.window->resize(1280, 720);
        QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
        QVERIFY(f.connectAndWait());
        QVERIFY(f.loadElementSets(kAllSets));
        QVERIFY(f.rehearseAt(QStringLiteral("2018-01-22T09:25:40Z"), 20.0));
        SchedulePanel *panel = scheduleTab(f);
        QVERIFY(!add(panel, QStringLiteral("FLOCK 2P-1")).isEmpty());
        QVERIFY(!add(panel, QStringLiteral("PERSEUS-M1")).isEmpty());
        if (!panel->isPreviewing())
            QVERIFY(waitForPreview(panel));
        auto *run = f.find<QPushButton>(QStringLiteral("scheduleRun"));
        QCOMPARE(run->text(), QStringLiteral("Run schedule"));
        QTest::mouseClick(run, Qt::LeftButton);
        slew::station::ScheduleRunner *runner = f.station.scheduleRunner();
        QVERIFY(runner->isRunning());
        QTRY_COMPARE(run->text(), QStringLiteral("Stop schedule"));
        QTRY_VERIFY_WITH_TIMEOUT(runner->current() && runner->current()->target == QStringLiteral("FLOCK 2P-1"), 20000);
        QTRY_VERIFY(f.find<QLabel>(QStringLiteral("scheduleState"))->text().contains(QStringLiteral("Now: FLOCK 2P-1")));
        QVERIFY(!panel->isPreviewing());
        QDir().mkpath(QStringLiteral("screenshots"));
        QVERIFY(f.window->grab().save(QStringLiteral("screenshots/schedule-running.png")));
        QTest::mouseClick(run, Qt::LeftButton);
        QVERIFY(!runner->isRunning());
        QTRY_COMPARE(run->text(), QStringLiteral("Run schedule"));
    }

    void theHorizonMaskIsDrawnOnThePlot()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("barn.horizon"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("0 3\n120 3\n120 25\n160 25\n160 3\n");
        file.close();
        WindowFixture f;
        QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
        slew::ui::StationDialog dialog(f.window.get());
        auto *station = dialog.findChild<QLineEdit *>(QStringLiteral("stationEdit"));
        auto *horizon = dialog.findChild<QLineEdit *>(QStringLiteral("stationHorizon"));
        auto *ok = dialog.findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok);
        station->setText(QStringLiteral("JO65hq"));
        horizon->setText(dir.filePath(QStringLiteral("missing.horizon")));
        QVERIFY(!ok->isEnabled()); // a mask that cannot be read holds OK back
        horizon->setText(path);
        QVERIFY(ok->isEnabled());
        QCOMPARE(dialog.findChild<QLabel *>(QStringLiteral("stationHorizonFeedback"))->text(),
                 QStringLiteral("Horizon mask: 5 points, 3.0° to 25.0° (highest at 120.0°)"));
        dialog.accept();
        QVERIFY(dialog.station().horizon);
        QCOMPARE(QSettings().value(QStringLiteral("sky/horizonFile")).toString(), path);
        f.station.setPlace(dialog.station());
        auto *plot = f.find<slew::ui::PolarPlotWidget>(QStringLiteral("polarPlot"));
        QVERIFY(plot);
        QVERIFY(plot->horizonMask());
        QCOMPARE(plot->horizonMask()->elevationAt(140), 25.0);
        // Kept: a new window's station comes with it.
        WindowFixture again;
        QVERIFY(again.station.place() && again.station.place()->horizon);
        QVERIFY(again.find<slew::ui::PolarPlotWidget>(QStringLiteral("polarPlot"))->horizonMask());
        QDir().mkpath(QStringLiteral("screenshots"));
        QVERIFY(f.window->grab().save(QStringLiteral("screenshots/horizon-on-plot.png")));
    }
};

QTEST_MAIN(SchedulePanelTest)
#include "tst_schedulepanel.moc"
