// SPDX-License-Identifier: GPL-3.0-or-later
// The value axis ticks of the telemetry charts, as a table: whole-number
// steps only, no repeated label, a flat series still gets a range, and no
// more ticks than the height allows.
#include "widgets/chartaxisticks.h"

#include <QSet>
#include <QTest>

#include <cmath>

using slew::ui::AxisTicks;
using slew::ui::ticksForHeight;
using slew::ui::wholeNumberTicks;

class TestChartAxisTicks : public QObject {
    Q_OBJECT
private slots:
    void ticks_data()
    {
        QTest::addColumn<double>("lo");
        QTest::addColumn<double>("hi");
        QTest::addColumn<int>("maxTicks");
        QTest::addColumn<double>("min");
        QTest::addColumn<double>("max");
        QTest::addColumn<double>("step");
        QTest::newRow("flat at zero") << 0.0 << 0.0 << 5 << -1.0 << 1.0 << 1.0;
        QTest::newRow("flat at 25") << 25.0 << 25.0 << 5 << 24.0 << 26.0 << 1.0;
        QTest::newRow("temperature creeping") << 25.0 << 25.6 << 5 << 24.0 << 26.0 << 1.0;
        QTest::newRow("a slew") << 0.0 << 300.0 << 5 << -24.0 << 324.0 << 100.0;
        QTest::newRow("small chart") << 0.0 << 30.0 << 3 << -2.4 << 32.4 << 20.0;
        QTest::newRow("negative speeds") << -6.2 << 0.0 << 5 << -6.696 << 0.496 << 2.0;
        QTest::newRow("no data") << qInf() << -qInf() << 5 << -0.08 << 1.08 << 1.0;
    }
    void ticks()
    {
        QFETCH(double, lo);
        QFETCH(double, hi);
        QFETCH(int, maxTicks);
        QFETCH(double, min);
        QFETCH(double, max);
        QFETCH(double, step);
        const AxisTicks t = wholeNumberTicks(lo, hi, maxTicks);
        QVERIFY2(std::abs(t.min - min) < 1e-9, qPrintable(QString::number(t.min)));
        QVERIFY2(std::abs(t.max - max) < 1e-9, qPrintable(QString::number(t.max)));
        QCOMPARE(t.step, step);
        QVERIFY(t.count >= 2 && t.count <= maxTicks);
        QVERIFY(t.firstTick >= t.min - 1e-9 && t.firstTick + (t.count - 1) * t.step <= t.max + 1e-9);
        QVERIFY(std::fmod(t.firstTick, t.step) == 0.0); // a multiple of the step
    }

    void labelsNeverRepeat()
    {
        for (double lo = -400; lo < 400; lo += 7.3) {
            for (double span : {0.0, 0.4, 3.0, 17.0, 250.0}) {
                for (int maxTicks = 2; maxTicks <= 6; ++maxTicks) {
                    const AxisTicks t = wholeNumberTicks(lo, lo + span, maxTicks);
                    QVERIFY(t.min <= lo && t.max >= lo + span);
                    QVERIFY(t.count >= 2);
                    QSet<QString> labels;
                    for (int i = 0; i < t.count; ++i)
                        labels.insert(QString::asprintf("%.0f", t.firstTick + i * t.step));
                    QCOMPARE(labels.size(), t.count);
                }
            }
        }
    }

    void heightDecidesTheTickCount()
    {
        QCOMPARE(ticksForHeight(0), 2);
        QCOMPARE(ticksForHeight(60), 3);
        QCOMPARE(ticksForHeight(1000), 6);
    }
};

QTEST_GUILESS_MAIN(TestChartAxisTicks)
#include "tst_chartaxisticks.moc"
