// TelemetryHistory: the reduced points keep every column's true minimum and
// maximum, whatever mix of block summaries and raw samples produced them.

#include "model/telemetryhistory.h"

#include <QRandomGenerator>
#include <QTest>

#include <cmath>
#include <map>

using slew::model::TelemetryHistory;

namespace {

struct Extremes {
    double min = INFINITY, max = -INFINITY;
};

// What each column must show, computed the slow and obvious way.
std::map<qint64, Extremes> bruteForce(const std::vector<std::pair<qint64, double>> &samples, qint64 from, qint64 to,
                                      int columns)
{
    std::map<qint64, Extremes> out;
    const double width = std::max(1.0, double(to - from + 1) / columns);
    for (auto [t, v] : samples) {
        if (t < from || t > to)
            continue;
        const qint64 c = std::min<qint64>(columns - 1, qint64((t - from) / width));
        out[c].min = std::min(out[c].min, double(float(v)));
        out[c].max = std::max(out[c].max, double(float(v)));
    }
    return out;
}

std::map<qint64, Extremes> byColumn(const QList<QPointF> &points, qint64 from, qint64 to, int columns)
{
    std::map<qint64, Extremes> out;
    const double width = std::max(1.0, double(to - from + 1) / columns);
    for (const QPointF &p : points) {
        const qint64 c = std::min<qint64>(columns - 1, qint64((qint64(p.x()) - from) / width));
        out[c].min = std::min(out[c].min, p.y());
        out[c].max = std::max(out[c].max, p.y());
    }
    return out;
}

void compare(const std::map<qint64, Extremes> &expected, const std::map<qint64, Extremes> &actual)
{
    QCOMPARE(actual.size(), expected.size());
    for (const auto &[column, e] : expected) {
        const auto it = actual.find(column);
        QVERIFY2(it != actual.end(), qPrintable(QStringLiteral("column %1 missing").arg(column)));
        QCOMPARE(it->second.min, e.min);
        QCOMPARE(it->second.max, e.max);
    }
}

} // namespace

class TestTelemetryHistory : public QObject {
    Q_OBJECT
private slots:
    void fewSamplesComeBackUnreduced()
    {
        TelemetryHistory h(1000);
        const int id = h.addSeries("az");
        for (int i = 0; i < 10; ++i)
            h.append(id, 1000 + i * 100, i);
        const QList<QPointF> points = h.decimated(id, 0, 10'000, 100);
        QCOMPARE(points.size(), 10);
        QCOMPARE(points.front(), QPointF(1000, 0));
        QCOMPARE(points.back(), QPointF(1900, 9));
    }

    void everyColumnKeepsItsMinimumAndMaximum_data()
    {
        QTest::addColumn<int>("samples");
        QTest::addColumn<int>("columns");
        QTest::addColumn<qint64>("fromOffset");
        QTest::addColumn<qint64>("toOffset");
        QTest::newRow("whole range, 1000 columns") << 200'000 << 1000 << qint64(0) << qint64(20'000'000);
        QTest::newRow("narrow columns, partial blocks") << 50'000 << 3000 << qint64(123'457) << qint64(4'000'001);
        QTest::newRow("wide columns") << 100'000 << 37 << qint64(0) << qint64(10'000'000);
        QTest::newRow("window inside the data") << 100'000 << 500 << qint64(2'500'050) << qint64(7'777'777);
    }

    void everyColumnKeepsItsMinimumAndMaximum()
    {
        QFETCH(int, samples);
        QFETCH(int, columns);
        QFETCH(qint64, fromOffset);
        QFETCH(qint64, toOffset);
        TelemetryHistory h(samples);
        const int id = h.addSeries("noise");
        QRandomGenerator rng(42);
        std::vector<std::pair<qint64, double>> raw;
        const qint64 start = 1'700'000'000'000;
        qint64 t = start;
        for (int i = 0; i < samples; ++i) {
            t += 50 + rng.bounded(100); // uneven spacing
            const double v = std::sin(i / 500.0) * 100 + rng.bounded(10.0) + (rng.bounded(1000) == 0 ? 500 : 0);
            raw.emplace_back(t, v);
            h.append(id, t, v);
        }
        const qint64 from = start + fromOffset, to = start + toOffset;
        const QList<QPointF> points = h.decimated(id, from, to, columns);
        QVERIFY(points.size() <= 2 * columns);
        compare(bruteForce(raw, from, to, columns), byColumn(points, from, to, columns));
        for (qsizetype i = 1; i < points.size(); ++i)
            QVERIFY(points[i - 1].x() <= points[i].x()); // in time order
    }

    void aSingleSpikeSurvivesADayAtTenHertz()
    {
        TelemetryHistory h;
        const int id = h.addSeries("load");
        const qint64 start = 1'700'000'000'000;
        const int n = 864'000, spikeAt = 432'123;
        for (int i = 0; i < n; ++i)
            h.append(id, start + qint64(i) * 100, i == spikeAt ? 99.0 : 1.0);
        const QList<QPointF> points = h.decimated(id, start, start + qint64(n) * 100, 800);
        QVERIFY(points.size() <= 1600);
        const auto spike = std::find_if(points.begin(), points.end(), [](const QPointF &p) { return p.y() == 99.0; });
        QVERIFY(spike != points.end());
        QCOMPARE(qint64(spike->x()), start + qint64(spikeAt) * 100);
        // 8 bytes a sample plus the block summaries, and nothing more.
        QVERIFY2(h.memoryBytes() < std::size_t(n) * 8 + std::size_t(n) / 4 + 4096,
                 qPrintable(QString::number(h.memoryBytes())));
    }

    void theRingKeepsOnlyTheNewestSamples()
    {
        TelemetryHistory h(1000);
        const int id = h.addSeries("el");
        std::vector<std::pair<qint64, double>> raw;
        QRandomGenerator rng(7);
        for (int i = 0; i < 5321; ++i) {
            const double v = rng.bounded(100.0);
            raw.emplace_back(qint64(i) * 10, v);
            h.append(id, qint64(i) * 10, v);
        }
        QCOMPARE(h.sampleCount(id), 1000);
        const std::vector<std::pair<qint64, double>> kept(raw.end() - 1000, raw.end());
        const QList<QPointF> points = h.decimated(id, 0, 60'000, 97);
        compare(bruteForce(kept, 0, 60'000, 97), byColumn(points, 0, 60'000, 97));
        int visited = 0;
        h.forEachSample(id, 0, 60'000, [&](qint64 t, double) {
            QVERIFY(t >= kept.front().first);
            ++visited;
        });
        QCOMPARE(visited, 1000);
    }

    void timeNeverGoesBackwards()
    {
        TelemetryHistory h(100);
        const int id = h.addSeries("t");
        h.append(id, 5000, 1);
        h.append(id, 4000, 2); // a clock step back
        h.append(id, 6000, 3);
        QList<qint64> times;
        h.forEachSample(id, 0, 10'000, [&](qint64 t, double) { times << t; });
        QCOMPARE(times, (QList<qint64>{5000, 5000, 6000}));
        QCOMPARE(h.lastSample(id), std::optional<QPointF>(QPointF(6000, 3)));
    }

    void rowsHoldEverySeriesAtEachTime()
    {
        TelemetryHistory h(100);
        const int az = h.addSeries("az"), el = h.addSeries("el"), gs = h.addSeries("gs");
        h.append(az, 1000, 16.04);
        h.append(el, 1000, 45.1);
        h.append(gs, 1500, 6);
        h.append(az, 2000, 17);
        h.append(az, 2000, 18); // a clock that stepped back: two samples at one time
        h.append(el, 3000, 46);
        QList<qint64> times;
        QList<QList<double>> rows;
        h.forEachRow({az, el, gs}, 1000, 2500, [&](qint64 t, const std::vector<double> &values) {
            times << t;
            rows << QList<double>(values.begin(), values.end());
        });
        QCOMPARE(times, (QList<qint64>{1000, 1500, 2000})); // 3000 lies outside
        QCOMPARE(rows[0][0], double(float(16.04)));
        QCOMPARE(rows[0][1], double(float(45.1)));
        QVERIFY(std::isnan(rows[0][2]));
        QVERIFY(std::isnan(rows[1][0]) && std::isnan(rows[1][1]));
        QCOMPARE(rows[1][2], 6.0);
        QCOMPARE(rows[2][0], 18.0); // the later of the two
        int none = 0;
        h.forEachRow({el}, 1001, 2999, [&](qint64, const std::vector<double> &) { ++none; });
        QCOMPARE(none, 0);
    }

    void theSampleBeforeAWindow()
    {
        TelemetryHistory h(100);
        const int gs = h.addSeries("gs");
        QVERIFY(!h.sampleBefore(gs, 5000));
        h.append(gs, 1000, 1);
        h.append(gs, 4000, 6);
        QCOMPARE(h.sampleBefore(gs, 4000), std::optional<QPointF>(QPointF(1000, 1)));
        QCOMPARE(h.sampleBefore(gs, 4001), std::optional<QPointF>(QPointF(4000, 6)));
        QVERIFY(!h.sampleBefore(gs, 1000));
    }

    void seriesAreIndependentAndNamed()
    {
        TelemetryHistory h(100);
        const int a = h.addSeries("a"), b = h.addSeries("b");
        h.append(a, 10, 1);
        h.append(b, 20, 2);
        h.append(b, 30, std::nan("")); // not a sample
        QCOMPARE(h.sampleCount(a), 1);
        QCOMPARE(h.sampleCount(b), 1);
        QCOMPARE(h.seriesId("b"), b);
        QCOMPARE(h.firstTimeMs(), std::optional<qint64>(10));
        h.clear();
        QCOMPARE(h.sampleCount(b), 0);
        QVERIFY(h.decimated(a, 0, 100, 10).isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestTelemetryHistory)
#include "tst_telemetryhistory.moc"
