// SPDX-License-Identifier: GPL-3.0-or-later
// The telemetry tab as an operator reads it: the status and error
// registers as named states, and the CSV export a spreadsheet takes as it
// is, one row per time with the values the controller sent.
#include "statuslanes.h"
#include "telemetrycharts.h"
#include "telemetrycsv.h"
#include "telemetryrecorder.h"
#include "windowfixture.h"

#include <QDateTime>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using slew::model::TelemetryHistory;
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

    void aFlappingRegisterCostsAStretchAPixel()
    {
        TelemetryHistory history;
        const int gs = history.addSeries(QStringLiteral("gs"));
        history.append(gs, 500, 1); // before the window: in force when it opens
        // 10 Hz alternation between moving and pointing, and one error.
        for (int i = 0; i < 600; ++i)
            history.append(gs, 1000 + i * 100, i == 300 ? 9 : (i % 2 ? 6 : 4));
        const std::vector<slew::ui::StatusStretch> stretches = slew::ui::statusStretches(history, gs, 1000, 61'000, 100);
        QVERIFY2(stretches.size() <= 101, qPrintable(QString::number(stretches.size())));
        QCOMPARE(stretches.front().fromMs, 1000);
        QCOMPARE(stretches.back().toMs, 61'000);
        for (std::size_t i = 1; i < stretches.size(); ++i)
            QCOMPARE(stretches[i].fromMs, stretches[i - 1].toMs); // no gaps, no overlaps
        const bool errorShown = std::any_of(stretches.begin(), stretches.end(), [](const slew::ui::StatusStretch &s) {
            return (s.bits & 8) && s.fromMs <= 31'000 && s.toMs >= 31'000;
        });
        QVERIFY(errorShown);

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
                                    QStringLiteral("Pointing error (deg)")};
        QCOMPARE(csvFields(lines.takeFirst()), header);
        QCOMPARE(lines.size(), 4); // one row per time, not per sample

        auto row = [&](qint64 t, std::initializer_list<std::pair<QString, QString>> cells) {
            QStringList expected(header.size());
            expected[0] = QDateTime::fromMSecsSinceEpoch(t, Qt::UTC).toString(Qt::ISODateWithMs);
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
                                               {QStringLiteral("Pointing error (deg)"), QStringLiteral("0.123")}}));
        QVERIFY(!lines[0].contains(QStringLiteral("16.040001")));
    }
};

QTEST_MAIN(TestTelemetryCharts)
#include "tst_telemetrycharts.moc"
