// SPDX-License-Identifier: GPL-3.0-or-later
// The History page (of the Tracking tab) on a real X11 server at 1280x720: the passes the station
// recorded, newest first, with their figures; the filter by target; a pass
// recorded while the tab is shown appears in it; Export CSV… in the
// telemetry export's conventions; the picture of the selected pass in a
// window of its own, and a dropped pass said to have none; a rehearsed pass
// marked as one in the table and the export. Nothing on the tab overlaps or
// is cut.

#include "layoutfaults.h"
#include "windowfixture.h"

#include "history/historypanel.h"
#include "history/passpicturedialog.h"
#include "linkschemes.h"
#include "operatortheme.h"
#include "records/passrecordstore.h"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QTabWidget>
#include <QScrollBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using slew::records::Outcome;
using slew::records::PassRecordStore;

namespace {

const QDateTime kAos = QDateTime::fromString(QStringLiteral("2018-01-22T09:15:45.000Z"), Qt::ISODateWithMs);

slew::records::PassPlanned planned(const QString &target, std::optional<int> norad, int minutesLater)
{
    slew::records::PassPlanned p;
    p.target = target;
    p.norad = norad;
    p.aos = kAos.addSecs(60 * minutesLater);
    p.tca = p.aos.addSecs(343);
    p.los = p.aos.addSecs(685);
    p.maxElevationDeg = 56.4;
    p.plannedWorstDeg = 0.22;
    return p;
}

// A pass from the north-east over to the south, the antenna a little behind.
void recordSamples(PassRecordStore *store, qint64 id, const QDateTime &aos, int count)
{
    for (int i = 0; i < count; ++i) {
        const double f = double(i) / (count - 1);
        const double az = 17 + 169 * f, el = 56.4 * std::sin(M_PI * f);
        const double error = 0.1 + 0.15 * std::sin(7 * M_PI * f) * std::sin(7 * M_PI * f);
        store->addSample(id, {aos.addMSecs(qint64(685000 * f)).toMSecsSinceEpoch(), az - error, el, az, el, error});
    }
}

void settle()
{
    for (int i = 0; i < 3; ++i)
        QCoreApplication::processEvents();
}

void shoot(QWidget *widget, const char *name)
{
    QDir().mkpath(QStringLiteral(SLEW_SCREENSHOT_DIR));
    widget->grab().save(QStringLiteral(SLEW_SCREENSHOT_DIR "/%1").arg(QLatin1String(name)));
}

} // namespace

class HistoryPanelTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QCOMPARE(QGuiApplication::platformName(), QStringLiteral("xcb"));
        WindowFixture::prepareApplication();
        slew::registerLinkSchemes();
        slew::ui::applyOperatorTheme(*qobject_cast<QApplication *>(QCoreApplication::instance()));
    }

    void listsFiltersExportsAndDraws()
    {
        QTemporaryDir dir;
        WindowFixture f;
        QCOMPARE(f.station.openPassRecords(dir.filePath(QStringLiteral("passes.sqlite")), 90), QString());
        PassRecordStore *store = f.station.passRecords();
        const qint64 flock = *store->beginPass(planned(QStringLiteral("FLOCK 2P-1"), 41617, 0));
        recordSamples(store, flock, kAos, 400);
        slew::records::PassFigures figures;
        figures.rmsDeg = 0.171;
        figures.worstDeg = 0.42;
        figures.commands = 117;
        figures.dopplerRmsHz = 2.0;
        figures.dopplerWorstHz = 13.7;
        store->setFigures(flock, figures);
        QVERIFY(store->finishPass(flock, Outcome::Tracked, {}, kAos.addSecs(685)));
        const qint64 sun = *store->beginPass(planned(QStringLiteral("the sun"), std::nullopt, 120));
        recordSamples(store, sun, kAos.addSecs(7200), 50);
        QVERIFY(store->finishPass(sun, Outcome::Interrupted, QStringLiteral("the link went down: sim: closed, by the peer"),
                                  kAos.addSecs(7300)));
        const qint64 iss = *store->recordDropped(planned(QStringLiteral("ISS (ZARYA)"), 25544, 240),
                                                 QStringLiteral("FLOCK 2P-1's pass had the rotator"));

        f.window->resize(1280, 720);
        QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
        slew::ui::HistoryPanel *history = f.window->historyPanel();
        f.window->bringToFront(history);
        settle();
        auto *table = f.find<QTableWidget>(QStringLiteral("historyTable"));
        QVERIFY(table);
        QCOMPARE(table->rowCount(), 3);
        // Newest first, with its figures.
        QCOMPARE(table->item(0, 0)->text(), QString::number(iss));
        QCOMPARE(table->item(0, 4)->text(), QStringLiteral("dropped"));
        QCOMPARE(table->item(0, 4)->toolTip(), QStringLiteral("FLOCK 2P-1's pass had the rotator"));
        QCOMPARE(table->item(2, 1)->text(), QStringLiteral("FLOCK 2P-1"));
        QCOMPARE(table->item(2, 2)->text(), QStringLiteral("2018-01-22 09:15"));
        QCOMPARE(table->item(2, 3)->text(), QStringLiteral("56.4°"));
        QCOMPARE(table->item(2, 5)->text(), QStringLiteral("0.171°"));
        QCOMPARE(table->item(2, 6)->text(), QStringLiteral("0.42°"));
        QCOMPARE(table->item(2, 7)->text(), QStringLiteral("117"));
        QCOMPARE(table->item(2, 8)->text(), QStringLiteral("2.0 Hz"));
        QCOMPARE(table->item(1, 8)->text(), QStringLiteral("—"));
        // Every figure in view at 1280x720, the Doppler column last: the
        // target's name gives way (whole in its tooltip).
        QVERIFY(!table->horizontalScrollBar()->isVisible());
        for (int column = 0; column < table->columnCount(); ++column) {
            const int right = table->columnViewportPosition(column) + table->columnWidth(column);
            QVERIFY2(right <= table->viewport()->width(),
                     qPrintable(QStringLiteral("column %1 ends at %2 of %3").arg(column).arg(right).arg(table->viewport()->width())));
        }
        QVERIFY(table->columnWidth(8) > table->fontMetrics().horizontalAdvance(table->item(2, 8)->text())); // "2.0 Hz" whole
        QCOMPARE(table->item(0, 1)->toolTip(), QStringLiteral("ISS (ZARYA)"));
        const QString faults = layoutFaults(f.window.get()).join(QLatin1Char('\n'));
        QVERIFY2(faults.isEmpty(), qPrintable(faults));
        QCOMPARE(f.window->size(), QSize(1280, 720));
        shoot(f.window.get(), "history-tab.png");

        // Filtered by target, in any case.
        QTest::keyClicks(f.find<QLineEdit>(QStringLiteral("historyFilter")), QStringLiteral("flock"));
        QTRY_COMPARE(table->rowCount(), 1);
        QCOMPARE(table->item(0, 1)->text(), QStringLiteral("FLOCK 2P-1"));
        QVERIFY(f.find<QLabel>(QStringLiteral("historyStatus"))->text().startsWith(QStringLiteral("1 pass matching")));
        f.find<QLineEdit>(QStringLiteral("historyFilter"))->clear();
        QTRY_COMPARE(table->rowCount(), 3);

        // A pass recorded while the tab is shown appears.
        const qint64 moon = *store->recordDropped(planned(QStringLiteral("the moon"), std::nullopt, 300),
                                                  QStringLiteral("below the horizon mask"));
        QTRY_COMPARE(table->rowCount(), 4);
        QCOMPARE(table->item(0, 0)->text(), QString::number(moon));

        // Export CSV: what is listed, as the telemetry export writes.
        const QString csv = dir.filePath(QStringLiteral("passes.csv"));
        QString error;
        QVERIFY2(history->exportCsv(csv, &error), qPrintable(error));
        QFile file(csv);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = file.readAll().split('\n');
        QCOMPARE(lines.size(), 6); // a header, four passes, and the last line's end
        QCOMPARE(lines[0], QByteArray("id,target,norad,aos_utc,tca_utc,los_utc,Max el (deg),Planned worst (deg),"
                                      "Pointing RMS (deg),Pointing worst (deg),commands,Doppler RMS (Hz),"
                                      "Doppler worst (Hz),outcome,reason,rehearsal,samples"));
        QCOMPARE(lines[4], QByteArray("1,FLOCK 2P-1,41617,2018-01-22T09:15:45.000Z,2018-01-22T09:21:28.000Z,"
                                      "2018-01-22T09:27:10.000Z,56.4,0.22,0.171,0.42,117,2,13.7,tracked,,no,400"));
        QCOMPARE(lines[3], QByteArray("2,the sun,,2018-01-22T11:15:45.000Z,2018-01-22T11:21:28.000Z,"
                                      "2018-01-22T11:27:10.000Z,56.4,0.22,,,,,,interrupted,"
                                      "\"the link went down: sim: closed, by the peer\",no,50"));

        // The picture of the selected pass, in a window of its own.
        table->selectRow(3);
        slew::ui::PassPictureDialog *picture = history->showSelectedPicture();
        QVERIFY(picture);
        QVERIFY(QTest::qWaitForWindowExposed(picture));
        QCOMPARE(picture->picture().size(), QSize(1200, 900));
        QVERIFY(!picture->isModal());
        settle();
        shoot(picture, "history-picture.png");
        picture->close();
        // A dropped pass has none, and says so.
        table->selectRow(1);
        QVERIFY(!history->showSelectedPicture());
        QCOMPARE(f.find<QLabel>(QStringLiteral("historyStatus"))->text(),
                 QStringLiteral("Pass %1 was dropped: it has no samples to draw.").arg(iss));
    }

    void marksRehearsedPasses()
    {
        QTemporaryDir dir;
        WindowFixture f;
        QCOMPARE(f.station.openPassRecords(dir.filePath(QStringLiteral("passes.sqlite")), 90), QString());
        PassRecordStore *store = f.station.passRecords();
        const qint64 real = *store->beginPass(planned(QStringLiteral("FLOCK 2P-1"), 41617, 0));
        QVERIFY(store->finishPass(real, Outcome::Tracked, {}, kAos.addSecs(685)));
        slew::records::PassPlanned practice = planned(QStringLiteral("FLOCK 2P-1"), 41617, 95);
        practice.rehearsal = true;
        const qint64 rehearsed = *store->beginPass(practice);
        recordSamples(store, rehearsed, practice.aos, 50);
        QVERIFY(store->finishPass(rehearsed, Outcome::Tracked, {}, practice.aos.addSecs(685)));

        f.window->resize(1280, 720);
        QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
        slew::ui::HistoryPanel *history = f.window->historyPanel();
        f.window->bringToFront(history);
        settle();
        auto *table = f.find<QTableWidget>(QStringLiteral("historyTable"));
        QCOMPARE(table->rowCount(), 2);
        // Newest first: the rehearsal, said so at its AOS, and the real pass as it was.
        QCOMPARE(table->item(0, 0)->text(), QString::number(rehearsed));
        QCOMPARE(table->item(0, 2)->text(), QStringLiteral("2018-01-22 10:50 · rehearsal"));
        QVERIFY(table->item(0, 2)->toolTip().startsWith(QStringLiteral("Rehearsed: by the rehearsal clock")));
        QCOMPARE(table->item(1, 2)->text(), QStringLiteral("2018-01-22 09:15"));
        QVERIFY(table->item(1, 2)->toolTip().isEmpty());
        const QString faults = layoutFaults(f.window.get()).join(QLatin1Char('\n'));
        QVERIFY2(faults.isEmpty(), qPrintable(faults));

        // The export says which was rehearsed, in its rehearsal column.
        const QString csv = dir.filePath(QStringLiteral("passes.csv"));
        QString error;
        QVERIFY2(history->exportCsv(csv, &error), qPrintable(error));
        QFile file(csv);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = file.readAll().split('\n');
        QCOMPARE(lines.size(), 4);
        const int column = int(lines[0].split(',').indexOf("rehearsal"));
        QVERIFY(column > 0);
        QCOMPARE(lines[1].split(',').at(column), QByteArray("yes"));
        QCOMPARE(lines[2].split(',').at(column), QByteArray("no"));
    }

    void saysWhenNoRecordsAreOpen()
    {
        WindowFixture f;
        f.window->resize(1280, 720);
        QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
        f.window->bringToFront(f.window->historyPanel());
        settle();
        QCOMPARE(f.find<QTableWidget>(QStringLiteral("historyTable"))->rowCount(), 0);
        QCOMPARE(f.find<QLabel>(QStringLiteral("historyStatus"))->text(),
                 QStringLiteral("No pass records are open: passes are not recorded."));
        const QString faults = layoutFaults(f.window.get()).join(QLatin1Char('\n'));
        QVERIFY2(faults.isEmpty(), qPrintable(faults));
    }
};

QTEST_MAIN(HistoryPanelTest)
#include "tst_historypanel.moc"
