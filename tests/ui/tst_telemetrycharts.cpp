// SPDX-License-Identifier: GPL-3.0-or-later
// The telemetry tab as an operator reads it: every chart's heading whole and
// every plot on one left edge at the window sizes operators use, with and
// without the pointing-error chart; the status and error registers as named
// states; the CSV export a spreadsheet takes as it is, one row per time
// with the values the controller sent; and during a rehearsal, the samples
// and the time axis in the station clock's time, said above the charts.
#include "stationwindow.h"
#include "telemetry/statuslaneview.h"
#include "telemetry/telemetrycharts.h"
#include "telemetry/telemetrycsv.h"
#include "telemetry/telemetryrecorder.h"
#include "windowfixture.h"

#include "sky/skyvector.h"
#include "sky/utctime.h"
#include "tracking/stationclock.h"
#include "tracking/timecontroller.h"

#include <QCategoryAxis>
#include <QChart>
#include <QChartView>
#include <QDateTime>
#include <QDateTimeAxis>
#include <QDir>
#include <QFile>
#include <QFontMetricsF>
#include <QLabel>
#include <QLayout>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>

using slew::model::TelemetryHistory;
using slew::ui::StatusLaneView;
using slew::ui::StatusTone;
using slew::ui::TelemetryCharts;
using slew::ui::TelemetryCsvColumn;
using slew::ui::TelemetryRecorder;
using Series = TelemetryRecorder::Series;

namespace {

// A history with the recorder's series, as the window has it.
void addRecorderSeries(TelemetryHistory &history)
{
    for (int s = 0; s < TelemetryRecorder::SeriesCount; ++s)
        history.addSeries(TelemetryRecorder::seriesLabel(Series(s)));
}

// A chart's plot area in the coordinates of the telemetry tab.
QRectF plotAreaIn(QWidget *charts, QChartView *view)
{
    const QRectF inScene = view->chart()->mapRectToScene(view->chart()->plotArea());
    const QPointF origin = view->viewport()->mapTo(charts, view->mapFromScene(QPointF(0, 0)));
    return inScene.translated(origin);
}

// Splits one CSV line into its fields (RFC 4180 quoting).
QStringList csvFields(const QString &line)
{
    QStringList out;
    QString field;
    bool quoted = false;
    for (qsizetype i = 0; i < line.size(); ++i) {
        const QChar c = line[i];
        if (quoted) {
            if (c == u'"' && i + 1 < line.size() && line[i + 1] == u'"') {
                field += u'"';
                ++i;
            } else if (c == u'"') {
                quoted = false;
            } else {
                field += c;
            }
        } else if (c == u'"') {
            quoted = true;
        } else if (c == u',') {
            out << field;
            field.clear();
        } else {
            field += c;
        }
    }
    out << field;
    return out;
}

} // namespace

class TestTelemetryCharts : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { WindowFixture::prepareApplication(); }

    void headingsAreWholeAndPlotsLineUp_data()
    {
        QTest::addColumn<QSize>("size");
        QTest::addColumn<bool>("pointing");
        QTest::newRow("1280x720") << QSize(1280, 720) << false;
        QTest::newRow("1280x720, pointing error") << QSize(1280, 720) << true;
        QTest::newRow("1440x900") << QSize(1440, 900) << false;
        QTest::newRow("1440x900, pointing error") << QSize(1440, 900) << true;
    }
    void headingsAreWholeAndPlotsLineUp()
    {
        QFETCH(QSize, size);
        QFETCH(bool, pointing);
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        // A screen of that size holds the window to it, as a window manager
        // does, whatever the window would ask for.
        f.window->layout()->setSizeConstraint(QLayout::SetNoConstraint);
        f.window->setMinimumSize(0, 0);
        f.window->resize(size);
        QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
        QVERIFY(f.connectAndWait());
        TelemetryCharts *charts = f.window->telemetryCharts();
        f.window->bringToFront(charts);
        if (pointing) {
            auto *recorder = f.window->findChild<TelemetryRecorder *>();
            QVERIFY(recorder);
            recorder->recordPointingError(0.25);
        }
        const int before = charts->redrawCount();
        QVERIFY(f.waitFor([&] { return charts->redrawCount() > before + 1; }, 10000));
        QCOMPARE(f.window->size(), size);

        const QStringList keys = {QStringLiteral("AzEl"), QStringLiteral("Speed"), QStringLiteral("Load"),
                                  QStringLiteral("Temp"), QStringLiteral("Status"), QStringLiteral("Pointing")};
        const QStringList titles = {QStringLiteral("Az/El (°)"), QStringLiteral("Speed (°/s)"), QStringLiteral("Load"),
                                    QStringLiteral("Temperature (°C)"), QStringLiteral("Status"),
                                    QStringLiteral("Pointing error (°)")};
        QList<QChartView *> shown;
        for (qsizetype i = 0; i < keys.size(); ++i) {
            auto *box = charts->findChild<QWidget *>(QStringLiteral("chart%1").arg(keys[i]));
            QVERIFY2(box, qPrintable(keys[i]));
            QCOMPARE(box->isVisible(), keys[i] != QLatin1String("Pointing") || pointing);
            if (!box->isVisible())
                continue;
            // The heading is whole: its full text, at no less than the width
            // it asks for, and the legend beside it at the height its words
            // need at its width.
            auto *title = charts->findChild<QLabel *>(QStringLiteral("chart%1Title").arg(keys[i]));
            QVERIFY2(title, qPrintable(keys[i]));
            QCOMPARE(title->text(), titles[i]);
            QVERIFY2(title->width() >= title->sizeHint().width(),
                     qPrintable(QStringLiteral("%1: %2 < %3").arg(keys[i]).arg(title->width()).arg(title->sizeHint().width())));
            auto *legend = charts->findChild<QLabel *>(QStringLiteral("chart%1Legend").arg(keys[i]));
            QVERIFY2(legend, qPrintable(keys[i]));
            QVERIFY2(legend->height() >= legend->heightForWidth(legend->width()), qPrintable(keys[i]));
            shown << charts->findChild<QChartView *>(QStringLiteral("chart%1View").arg(keys[i]));
            QVERIFY(shown.back());
        }
        QCOMPARE(shown.size(), pointing ? 6 : 5);

        // Every plot on one left and one right edge, and tall enough to read.
        auto describe = [&] {
            QStringList out;
            for (QChartView *view : shown) {
                const QRectF r = plotAreaIn(charts, view);
                out << QStringLiteral("%1 %2..%3 h %4").arg(view->objectName()).arg(r.left()).arg(r.right()).arg(r.height());
            }
            return out.join(QStringLiteral("; "));
        };
        auto linedUp = [&] {
            const QRectF first = plotAreaIn(charts, shown.front());
            for (QChartView *view : shown) {
                const QRectF r = plotAreaIn(charts, view);
                if (std::abs(r.left() - first.left()) > 1.0 || std::abs(r.right() - first.right()) > 1.0)
                    return false;
            }
            return true;
        };
        QVERIFY2(f.waitFor(linedUp, 5000), qPrintable(describe()));
        for (QChartView *view : shown)
            QVERIFY2(plotAreaIn(charts, view).height() >= 30, qPrintable(describe()));
        QDir().mkpath(QStringLiteral("screenshots"));
        QVERIFY(f.window->grab().save(QStringLiteral("screenshots/telemetry-%1x%2%3.png")
                                          .arg(size.width())
                                          .arg(size.height())
                                          .arg(pointing ? QStringLiteral("-pointing") : QString())));
    }

    void aRehearsalIsChartedInTheStationClocksTime()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        auto *recorder = f.window->findChild<TelemetryRecorder *>();
        QVERIFY(recorder);
        TelemetryCharts *charts = f.window->telemetryCharts();
        f.window->tabs()->setCurrentWidget(charts);
        // As the window wires them: both follow the station clock.
        recorder->followClock(f.station.clock());
        charts->followClock(f.station.clock());
        QVERIFY(f.connectAndWait());
        const int az = Series::AzActual;
        const TelemetryHistory &history = recorder->history();
        const auto msFrom = [](double julian) { return slew::sky::unixSecondsFromJulian(julian) * 1000.0; };
        // The newest position sample within `seconds` after `fromMs`.
        const auto recordedFrom = [&](double fromMs, double seconds) {
            const std::optional<QPointF> last = history.lastSample(az);
            return last && last->x() >= fromMs && last->x() <= fromMs + seconds * 1000.0;
        };
        const auto axisEnd = [&] {
            auto *view = charts->findChild<QChartView *>(QStringLiteral("chartAzElView"));
            auto *axis = view ? qobject_cast<QDateTimeAxis *>(view->chart()->axes(Qt::Horizontal).value(0)) : nullptr;
            return axis ? axis->max() : QDateTime();
        };
        const double realStart = msFrom(slew::sky::julianNow()) - 1000.0;
        QVERIFY(f.waitFor([&] { return recordedFrom(realStart, 30); }, 10000));
        QVERIFY(charts->rehearsalLine()->isHidden());

        // A rehearsal of another day: a record of its own, in its time.
        const double start = *slew::sky::julianFromIso(QStringLiteral("2018-01-22T07:40:00Z"));
        f.window->timeController()->rehearse(start, 5.0);
        QCOMPARE(history.sampleCount(az), 0);
        QVERIFY(f.waitFor([&] { return recordedFrom(msFrom(start), 60); }, 10000));
        QVERIFY(f.waitFor([&] { return axisEnd().date() == QDate(2018, 1, 22); }, 10000));
        QVERIFY(charts->rehearsalLine()->isVisible());
        QCOMPARE(charts->rehearsalLine()->text(), QStringLiteral("REHEARSAL: the times are the station clock's (×5)"));
        // Paused, it says so.
        f.station.clock()->pause();
        QCOMPARE(charts->rehearsalLine()->text(),
                 QStringLiteral("REHEARSAL: the times are the station clock's (×5, paused)"));

        // Real time again: a new record, and the mark gone.
        f.window->timeController()->followRealTime();
        QCOMPARE(history.sampleCount(az), 0);
        const double back = msFrom(slew::sky::julianNow()) - 1000.0;
        QVERIFY(f.waitFor([&] { return recordedFrom(back, 30); }, 10000));
        QVERIFY(f.waitFor([&] { return axisEnd().date() >= QDateTime::currentDateTimeUtc().date().addDays(-1); }, 10000));
        QVERIFY(charts->rehearsalLine()->isHidden());
    }

    void statusRegistersAreNamedStates()
    {
        TelemetryHistory history;
        addRecorderSeries(history);
        const qint64 now = QDateTime::currentMSecsSinceEpoch();
        history.append(Series::AzStatus, now - 50'000, 1);  // idle
        history.append(Series::AzStatus, now - 30'000, 6);  // the position servo at work
        history.append(Series::ElStatus, now - 50'000, 9);  // idle, error
        history.append(Series::ErrorFlags, now - 50'000, 1); // SatNOGS' "no error"
        history.append(Series::ErrorFlags, now - 20'000, 8);

        TelemetryCharts charts(&history);
        charts.resize(700, 900);
        charts.show();
        QVERIFY(QTest::qWaitForWindowExposed(&charts));
        charts.setPaused(true); // the view stays where this test looks
        StatusLaneView *lanes = charts.statusLanes();
        QVERIFY(lanes);
        QVERIFY(WindowFixture::waitFor([&] { return lanes->chart()->plotArea().height() > 30; }, 5000));
        QCOMPARE(charts.findChild<QChartView *>(QStringLiteral("chartStatusView")), lanes);

        // The lanes are named where the other charts have numbers.
        QCOMPARE(lanes->laneAxis()->categoriesLabels(),
                 (QStringList{QStringLiteral("GE"), QStringLiteral("GS el"), QStringLiteral("GS az")}));
        // Each stretch holds from one change to the next.
        QCOMPARE(lanes->stretches(0).size(), size_t(2));
        QCOMPARE(lanes->stretches(0)[1].bits, 6);
        QCOMPARE(lanes->stretches(0)[1].fromMs, now - 30'000);

        // What the operator reads, pointing at each lane.
        const QRectF plot = lanes->chart()->mapRectToScene(lanes->chart()->plotArea());
        const qint64 from = now - charts.windowMs();
        auto at = [&](qint64 t, int row) {
            const double x = plot.left() + plot.width() * double(t - from) / double(charts.windowMs());
            const double y = plot.top() + plot.height() * (row + 0.5) / 3.0;
            return lanes->mapFromScene(QPointF(x, y));
        };
        const QString azMoving = lanes->describeAt(at(now - 10'000, 0));
        QVERIFY2(azMoving.startsWith(QStringLiteral("GS az")), qPrintable(azMoving));
        QVERIFY2(azMoving.contains(QStringLiteral("moving, pointing (0x06)")), qPrintable(azMoving));
        QVERIFY2(lanes->describeAt(at(now - 40'000, 0)).contains(QStringLiteral("idle (0x01)")),
                 qPrintable(lanes->describeAt(at(now - 40'000, 0))));
        QVERIFY2(lanes->describeAt(at(now - 10'000, 1)).contains(QStringLiteral("idle, error (0x09)")),
                 qPrintable(lanes->describeAt(at(now - 10'000, 1))));
        QVERIFY2(lanes->describeAt(at(now - 40'000, 2)).contains(QStringLiteral("no error (0x01)")),
                 qPrintable(lanes->describeAt(at(now - 40'000, 2))));
        QVERIFY2(lanes->describeAt(at(now - 10'000, 2)).contains(QStringLiteral("motor error (0x08)")),
                 qPrintable(lanes->describeAt(at(now - 10'000, 2))));

        // Drawn in the colour of the state that matters most: moving for
        // the servo at work, error wherever the error bit is set.
        const QImage image = lanes->grab().toImage();
        auto colourAt = [&](qint64 t, int row) {
            const QPoint p = at(t, row);
            return image.pixelColor(p.x(), p.y() + 2).rgb(); // below the middle, clear of the names
        };
        QCOMPARE(colourAt(now - 2'000, 0), slew::ui::toneColour(StatusTone::Moving).rgb());
        QCOMPARE(colourAt(now - 2'000, 1), slew::ui::toneColour(StatusTone::Error).rgb());
        QCOMPARE(colourAt(now - 2'000, 2), slew::ui::toneColour(StatusTone::Error).rgb());

        // An azimuth-only rotator has no elevation lane.
        charts.setElevationShown(false);
        QCOMPARE(lanes->laneAxis()->categoriesLabels(), (QStringList{QStringLiteral("GE"), QStringLiteral("GS az")}));

        // A short stretch shows whole names or none: "no error" never
        // becomes "no …", which reads as its opposite.
        const QFontMetricsF metrics(lanes->laneAxis()->labelsFont());
        const QString noError = QStringLiteral("no error");
        QCOMPARE(slew::ui::fittedStateName(noError, metrics, metrics.horizontalAdvance(noError)), noError);
        QCOMPARE(slew::ui::fittedStateName(noError, metrics, metrics.horizontalAdvance(noError) - 1), QString());
        const QString cut = QStringLiteral("moving, …");
        QCOMPARE(slew::ui::fittedStateName(QStringLiteral("moving, pointing"), metrics, metrics.horizontalAdvance(cut)), cut);
        QCOMPARE(slew::ui::fittedStateName(QStringLiteral("moving, pointing"), metrics, 2.0), QString());
    }

    void aFlappingRegisterCostsAStretchAPixel()
    {
        TelemetryHistory history;
        const int gs = history.addSeries(QStringLiteral("gs"));
        history.append(gs, 500, 1); // before the window: in force when it opens
        // 10 Hz alternation between moving and pointing, and one error.
        for (int i = 0; i < 600; ++i)
            history.append(gs, 1000 + i * 100, i == 300 ? 9 : (i % 2 ? 6 : 4));
        const std::vector<slew::ui::StatusStretch> stretches = slew::ui::statusStretches(history, gs, 1000, 61'000, 100);
        QVERIFY2(stretches.size() <= 2 * 100 + 1, qPrintable(QString::number(stretches.size())));
        QCOMPARE(stretches.front().fromMs, 1000);
        QCOMPARE(stretches.back().toMs, 61'000);
        for (std::size_t i = 1; i < stretches.size(); ++i)
            QCOMPARE(stretches[i].fromMs, stretches[i - 1].toMs); // no gaps, no overlaps
        const bool errorShown = std::any_of(stretches.begin(), stretches.end(), [](const slew::ui::StatusStretch &s) {
            return (s.bits & 8) && s.fromMs <= 31'000 && s.toMs >= 31'000;
        });
        QVERIFY(errorShown);

        // A change a moment after another shows both in that column only;
        // the value in force after it is the later one alone.
        TelemetryHistory quick;
        const int az = quick.addSeries(QStringLiteral("gs az"));
        quick.append(az, 10'000, 1);
        quick.append(az, 10'050, 6);
        quick.append(az, 30'000, 4); // arrived
        const std::vector<slew::ui::StatusStretch> blurred = slew::ui::statusStretches(quick, az, 1000, 61'000, 600);
        QCOMPARE(blurred.size(), size_t(3));
        QCOMPARE(blurred[0].bits, 7);
        QCOMPARE(blurred[0].toMs, 10'100); // one column: 100 ms
        QCOMPARE(blurred[1].fromMs, 10'100);
        QCOMPARE(blurred[1].toMs, 30'000);
        QCOMPARE(blurred[1].bits, 6);
        QCOMPARE(blurred[2].toMs, 61'000);
        QCOMPARE(blurred[2].bits, 4);

        // Sparse changes come back exactly.
        TelemetryHistory sparse;
        const int ge = sparse.addSeries(QStringLiteral("ge"));
        sparse.append(ge, 2000, 1);
        sparse.append(ge, 9000, 8);
        sparse.append(ge, 9500, 8); // the same again
        const std::vector<slew::ui::StatusStretch> two = slew::ui::statusStretches(sparse, ge, 1000, 61'000, 600);
        QCOMPARE(two.size(), size_t(2));
        QCOMPARE(two[0].fromMs, 2000);
        QCOMPARE(two[0].toMs, 9000);
        QCOMPARE(two[0].bits, 1);
        QCOMPARE(two[1].toMs, 61'000);
        QCOMPARE(two[1].bits, 8);
    }

    void csvValues_data()
    {
        QTest::addColumn<int>("kind");
        QTest::addColumn<int>("decimals");
        QTest::addColumn<double>("value");
        QTest::addColumn<QString>("expected");
        const int number = int(TelemetryCsvColumn::Kind::Number);
        const int axis = int(TelemetryCsvColumn::Kind::AxisStatus);
        const int errors = int(TelemetryCsvColumn::Kind::ErrorFlags);
        QTest::newRow("two decimals") << number << -1 << 16.04 << "16.04";
        QTest::newRow("near a turn") << number << -1 << 359.99 << "359.99";
        QTest::newRow("one decimal") << number << -1 << 45.1 << "45.1";
        QTest::newRow("negative") << number << -1 << -0.5 << "-0.5";
        QTest::newRow("whole") << number << -1 << 30.0 << "30";
        QTest::newRow("negative zero") << number << -1 << -0.0 << "0";
        QTest::newRow("sum of an offset") << number << -1 << 16.04 + 0.25 << "16.29";
        QTest::newRow("rounded") << number << 3 << 0.1234567 << "0.123";
        QTest::newRow("rounded, no trailing zeros") << number << 3 << 1.5 << "1.5";
        QTest::newRow("no sample") << number << -1 << qQNaN() << "";
        QTest::newRow("GS servo") << axis << -1 << 6.0 << "0x06 moving, pointing";
        QTest::newRow("GS idle and error") << axis << -1 << 9.0 << "0x09 idle, error";
        QTest::newRow("GE none") << errors << -1 << 1.0 << "0x01 no error";
        QTest::newRow("GE two") << errors << -1 << 10.0 << "0x0a sensor error, motor error";
    }
    void csvValues()
    {
        QFETCH(int, kind);
        QFETCH(int, decimals);
        QFETCH(double, value);
        QFETCH(QString, expected);
        TelemetryCsvColumn column;
        column.kind = TelemetryCsvColumn::Kind(kind);
        column.decimals = decimals;
        // Through the history, as the export has it: stored as a float.
        TelemetryHistory history;
        const int id = history.addSeries(QStringLiteral("x"));
        history.append(id, 1000, value);
        double stored = qQNaN();
        history.forEachSample(id, 0, 2000, [&](qint64, double v) { stored = v; });
        QCOMPARE(QString::fromUtf8(slew::ui::telemetryCsvValue(column, stored)), expected);
    }

    void csvHasOneRowPerTimeAtTheControllersPrecision()
    {
        TelemetryHistory history;
        addRecorderSeries(history);
        const qint64 now = QDateTime::currentMSecsSinceEpoch();
        const qint64 t1 = now - 3000, t2 = now - 2500, t3 = now - 2000, t4 = now - 1000;
        history.append(Series::AzActual, t1, 16.04);
        history.append(Series::ElActual, t1, 45.1);
        history.append(Series::AzVelocity, t2, 2.5);
        history.append(Series::Temperature, t2, 25.31);
        history.append(Series::AzStatus, t3, 6);
        history.append(Series::ErrorFlags, t3, 12);
        history.append(Series::AzActual, t4, 359.99);
        history.append(Series::ElActual, t4, -0.5);
        history.append(Series::PointingError, t4, 0.1234567);
        history.append(Series::ReceiveDopplerError, t4, -2.345);

        TelemetryCharts charts(&history);
        charts.setWindowMs(5 * 60 * 1000);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("t.csv"));
        QString error;
        QVERIFY2(charts.exportCsv(path, &error), qPrintable(error));
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly | QIODevice::Text));
        QStringList lines = QString::fromUtf8(file.readAll()).split(u'\n');
        QCOMPARE(lines.takeLast(), QString()); // the last row ends its line too

        const QStringList header = {QStringLiteral("time_utc"),        QStringLiteral("unix_ms"),
                                    QStringLiteral("Az (deg)"),        QStringLiteral("El (deg)"),
                                    QStringLiteral("Az commanded (deg)"), QStringLiteral("El commanded (deg)"),
                                    QStringLiteral("Az speed (deg/s)"), QStringLiteral("El speed (deg/s)"),
                                    QStringLiteral("Az load"),         QStringLiteral("El load"),
                                    QStringLiteral("Temperature (degC)"), QStringLiteral("GS az"),
                                    QStringLiteral("GS el"),           QStringLiteral("GE"),
                                    QStringLiteral("Pointing error (deg)"),
                                    QStringLiteral("Receive Doppler error (Hz)"),
                                    QStringLiteral("Transmit Doppler error (Hz)")};
        QCOMPARE(csvFields(lines.takeFirst()), header);
        QCOMPARE(lines.size(), 4); // one row per time, not per sample

        auto row = [&](qint64 t, std::initializer_list<std::pair<QString, QString>> cells) {
            QStringList expected(header.size());
            expected[0] = slew::sky::utcFromUnixMs(t).toString(Qt::ISODateWithMs);
            expected[1] = QString::number(t);
            for (const auto &[name, value] : cells)
                expected[header.indexOf(name)] = value;
            return expected;
        };
        QCOMPARE(csvFields(lines[0]), row(t1, {{QStringLiteral("Az (deg)"), QStringLiteral("16.04")},
                                               {QStringLiteral("El (deg)"), QStringLiteral("45.1")}}));
        QCOMPARE(csvFields(lines[1]), row(t2, {{QStringLiteral("Az speed (deg/s)"), QStringLiteral("2.5")},
                                               {QStringLiteral("Temperature (degC)"), QStringLiteral("25.31")}}));
        QCOMPARE(csvFields(lines[2]),
                 row(t3, {{QStringLiteral("GS az"), QStringLiteral("0x06 moving, pointing")},
                          {QStringLiteral("GE"),
                           QStringLiteral("0x0c homing error, motor error, possible over-temperature")}}));
        QCOMPARE(csvFields(lines[3]), row(t4, {{QStringLiteral("Az (deg)"), QStringLiteral("359.99")},
                                               {QStringLiteral("El (deg)"), QStringLiteral("-0.5")},
                                               {QStringLiteral("Pointing error (deg)"), QStringLiteral("0.123")},
                                               {QStringLiteral("Receive Doppler error (Hz)"), QStringLiteral("-2.3")}}));
        QVERIFY(!lines[0].contains(QStringLiteral("16.040001")));
    }
};

QTEST_MAIN(TestTelemetryCharts)
#include "tst_telemetrycharts.moc"
