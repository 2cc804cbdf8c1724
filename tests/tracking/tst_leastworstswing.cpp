// SPDX-License-Identifier: GPL-3.0-or-later
// The least-worst azimuth swing on its own: it follows what the axis can
// follow exactly, keeps within the rate and the travel, meets the worst it
// reports, and that worst is the least: a little less cannot be driven.

#include "tracking/leastworstswing.h"
#include "tracking/passplanner.h"
#include "syntheticpass.h"

#include <QTest>

#include <cmath>

using namespace slew::tracking;

namespace {

// The worst angle on the sky between the antenna (the swing's azimuth, the
// elevation on its plane) and the target, over the points.
double worstOnTheSky(const QList<SwingPoint> &points, const QList<double> &azimuth)
{
    double worst = 0;
    for (int i = 0; i < points.size(); ++i) {
        const double el = elevationOnPlane(points[i].skyElevation, azimuth[i] - points[i].azimuth);
        worst = std::max(worst, skyAngleDeg(azimuth[i], el, points[i].azimuth, points[i].skyElevation));
    }
    return worst;
}

double fastestTurn(const QList<SwingPoint> &points, const QList<double> &azimuth)
{
    double fastest = 0;
    for (int i = 1; i < points.size(); ++i)
        fastest = std::max(fastest, std::abs(azimuth[i] - azimuth[i - 1]) / (points[i].seconds - points[i - 1].seconds));
    return fastest;
}

} // namespace

class LeastWorstSwingTest : public QObject {
    Q_OBJECT
private slots:
    void elevationOnThePlane()
    {
        QCOMPARE(elevationOnPlane(40.0, 0.0), 40.0);
        QCOMPARE(elevationOnPlane(40.0, 90.0), 90.0); // a quarter turn off: the zenith is nearest
        QCOMPARE(elevationOnPlane(40.0, -120.0), 90.0);
        QCOMPARE(elevationOnPlane(90.0, 30.0), 90.0);
        // tan(el') = tan(45°) / cos(60°) = 2
        QVERIFY(std::abs(elevationOnPlane(45.0, 60.0) - std::atan(2.0) * 180.0 / M_PI) < 1e-9);
        QVERIFY(std::abs(elevationOnPlane(45.0, -60.0) - elevationOnPlane(45.0, 60.0)) < 1e-12);
    }

    void aPassTheAxisKeepsUpWithIsFollowedExactly()
    {
        const QList<SwingPoint> points = unwrappedSwing(greatCirclePass(200.0, 45.0, true));
        const LeastWorstSwing swing = leastWorstSwing(points, 6.0, 0.0, 450.0);
        QCOMPARE(swing.azimuth.size(), points.size());
        QCOMPARE(swing.worstDeg, 0.0);
        for (int i = 0; i < points.size(); ++i)
            QCOMPARE(swing.azimuth[i], points[i].azimuth);
    }

    // Passes that miss the zenith by 0.5° and by 2.9°, swept at 0.5°/s of
    // arc, on an axis of 5.9°/s (a G-5500 a little under its full rate).
    void theSwingNearTheZenithIsTheLeastWorst_data()
    {
        QTest::addColumn<double>("maxEl");
        QTest::addRow("0.5 deg off") << 89.5;
        QTest::addRow("2.9 deg off") << 87.1;
    }
    void theSwingNearTheZenithIsTheLeastWorst()
    {
        QFETCH(double, maxEl);
        constexpr double kRate = 5.9;
        const QList<SwingPoint> points = unwrappedSwing(greatCirclePass(30.0, maxEl, true, 0.5, 0.5));
        const LeastWorstSwing swing = leastWorstSwing(points, kRate, -180.0, 540.0);
        QCOMPARE(swing.azimuth.size(), points.size());
        QVERIFY(swing.worstDeg > 0);

        // Within the rate, and as good on the sky as it says: the worst is
        // met (to the bisection's precision), not merely bounded.
        QVERIFY2(fastestTurn(points, swing.azimuth) <= kRate + 1e-6,
                 qPrintable(QString::number(fastestTurn(points, swing.azimuth))));
        const double measured = worstOnTheSky(points, swing.azimuth);
        qInfo("%.1f deg: least worst %.3f deg, measured %.3f deg", maxEl, swing.worstDeg, measured);
        QVERIFY2(measured <= swing.worstDeg + 1e-4 && measured > swing.worstDeg - 0.01,
                 qPrintable(QStringLiteral("%1 against %2").arg(measured).arg(swing.worstDeg)));

        // The least: a slightly faster axis does better, a slightly slower
        // one worse, so the figure is set by the rate and nothing else.
        QVERIFY(leastWorstSwing(points, kRate * 1.1, -180.0, 540.0).worstDeg < swing.worstDeg);
        QVERIFY(leastWorstSwing(points, kRate * 0.9, -180.0, 540.0).worstDeg > swing.worstDeg);

        // Against chasing the bearing at full rate, as a plain tracker does.
        QList<double> chased{points.front().azimuth};
        for (int i = 1; i < points.size(); ++i) {
            const double step = kRate * (points[i].seconds - points[i - 1].seconds);
            chased.append(chased.back() + std::clamp(points[i].azimuth - chased.back(), -step, step));
        }
        const double chasing = worstOnTheSky(points, chased);
        qInfo("  chasing: %.3f deg", chasing);
        QVERIFY(swing.worstDeg < 0.75 * chasing);

        // Away from the top it follows the target exactly.
        QCOMPARE(swing.azimuth.front(), points.front().azimuth);
        QCOMPARE(swing.azimuth.back(), points.back().azimuth);
    }

    // A swing that would run past the end stop is kept inside the travel,
    // and is worse for it, not unsafe.
    void theTravelBoundsTheSwing()
    {
        const QList<SwingPoint> points = unwrappedSwing(greatCirclePass(30.0, 88.0, true, 0.5, 0.5));
        double low = 1e9, high = -1e9;
        for (const SwingPoint &p : points) {
            low = std::min(low, p.azimuth);
            high = std::max(high, p.azimuth);
        }
        const LeastWorstSwing free = leastWorstSwing(points, 5.9, -180.0, 540.0);
        const LeastWorstSwing bounded = leastWorstSwing(points, 5.9, low, high);
        QCOMPARE(bounded.azimuth.size(), points.size());
        for (double az : bounded.azimuth)
            QVERIFY(az >= low - 1e-9 && az <= high + 1e-9);
        QVERIFY(bounded.worstDeg >= free.worstDeg - 1e-6);
    }

    void badInputGivesNoPath()
    {
        QVERIFY(leastWorstSwing({}, 6.0, 0, 360).azimuth.isEmpty());
        const QList<SwingPoint> backwards{{10, 0, 10}, {5, 1, 11}};
        QVERIFY(leastWorstSwing(backwards, 6.0, 0, 360).azimuth.isEmpty());
        const QList<SwingPoint> ok{{0, 0, 10}, {1, 1, 11}};
        QVERIFY(leastWorstSwing(ok, 0.0, 0, 360).azimuth.isEmpty());
        QVERIFY(leastWorstSwing(ok, 6.0, 360, 0).azimuth.isEmpty());
    }
};

QTEST_GUILESS_MAIN(LeastWorstSwingTest)
#include "tst_leastworstswing.moc"
