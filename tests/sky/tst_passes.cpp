// SPDX-License-Identifier: GPL-3.0-or-later
// Pass prediction against a brute-force scan of the elevation every 0.1 s
// (AOS and LOS within 1 s, the same passes found), all satellites sorted by
// AOS, the engine on made-up elevation curves, and the sun's and moon's
// rise, culmination and set against PyEphem.

#include "sky/tleformat.h"
#include "sky/passes.h"

#include <QFile>
#include <QSet>
#include <QProcess>
#include <QTest>

#include <algorithm>
#include <atomic>
#include <limits>

using namespace slew::sky;

Q_DECLARE_METATYPE(slew::sky::Site)

namespace {

const QString kPython = QStringLiteral("/usr/bin/python3");

QList<ElementSet> snapshot()
{
    QFile file(QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle"));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return readTleText(QString::fromLatin1(file.readAll())).sets;
}

const ElementSet *named(const QList<ElementSet> &sets, const QString &name)
{
    const QList<const ElementSet *> found = findSatellites(sets, name);
    return found.isEmpty() ? nullptr : found.first();
}

struct BrutePass {
    double aos = 0, los = 0, maxElevation = -90;
};

// Every 0.1 s: AOS is the first sample at or above the threshold, LOS the last.
QList<BrutePass> bruteForce(const Sgp4 &sat, const Site &station, const PassWindow &w)
{
    QList<BrutePass> passes;
    const double step = 0.1 / kSecondsPerDay;
    bool up = false;
    BrutePass current;
    double lastUp = 0;
    const long samples = long((w.endJulian - w.startJulian) / step);
    for (long i = 0; i <= samples; ++i) {
        const double t = w.startJulian + i * step;
        LookAngles look;
        const bool ok = observeSatellite(sat, station, t, &look);
        const bool above = ok && look.elevationDeg >= w.minElevationDeg;
        if (above && !up) {
            current = BrutePass();
            current.aos = t;
        }
        if (above) {
            lastUp = t;
            current.maxElevation = std::max(current.maxElevation, look.elevationDeg);
        }
        if (!above && up) {
            current.los = lastUp;
            passes.append(current);
        }
        up = above;
    }
    return passes;
}

} // namespace

class TestPasses : public QObject {
    Q_OBJECT
private slots:
    void engineOnMadeUpCurves();
    void matchesBruteForce_data();
    void matchesBruteForce();
    void allSatellitesSortedByAos();
    void decayedSatelliteHasNoPasses();
    void searchEndsOnAnyInput();
    void sunAndMoonAgreeWithPyEphem();
};

void TestPasses::engineOnMadeUpCurves()
{
    // Elevation 10·sin(2π t / 1 day) degrees: up from t = 0 to 0.5 day.
    const ElevationFunction sine = [](double t) {
        return ElevationSample{10.0 * std::sin(kTwoPi * t), t * 360.0};
    };
    PassScan scan;
    scan.maxElevationRateDegS = 10.0 * kTwoPi / kSecondsPerDay * 1.01;
    const QList<Pass> passes = scanPasses(sine, {-0.25, 1.6, 5.0}, scan);
    QCOMPARE(passes.size(), 2);
    // sin = 0.5 at 1/12 and 5/12 of a day.
    QVERIFY(std::fabs(passes[0].aos.julian - 1.0 / 12.0) * kSecondsPerDay < 0.02);
    QVERIFY(std::fabs(passes[0].los.julian - 5.0 / 12.0) * kSecondsPerDay < 0.02);
    QVERIFY(std::fabs(passes[0].tca.julian - 0.25) * kSecondsPerDay < 0.5);
    QVERIFY(std::fabs(passes[0].maxElevationDeg() - 10.0) < 1e-6);
    QVERIFY(std::fabs(passes[0].tca.azimuthDeg - 90.0) < 0.01);
    QVERIFY(!passes[0].aosClipped && !passes[0].losClipped);
    // The second pass starts before the window's end and is followed to its LOS.
    QVERIFY(std::fabs(passes[1].los.julian - (1.0 + 5.0 / 12.0)) * kSecondsPerDay < 0.02);

    // Already up when the window opens.
    const QList<Pass> clipped = scanPasses(sine, {0.2, 0.6, 5.0}, scan);
    QCOMPARE(clipped.size(), 1);
    QVERIFY(clipped[0].aosClipped);
    QCOMPARE(clipped[0].aos.julian, 0.2);

    // Never up.
    QVERIFY(scanPasses(sine, {0.0, 3.0, 11.0}, scan).isEmpty());
}

void TestPasses::matchesBruteForce_data()
{
    QTest::addColumn<QString>("satellite");
    QTest::addColumn<double>("minElevation");
    QTest::addColumn<Site>("station");
    const Site copenhagen{55.6875, 12.625, 20, {}, {}};
    const Site quito{-0.2, -78.5, 2850, {}, {}};
    QTest::newRow("ISS, horizon") << QStringLiteral("ISS (ZARYA)") << 0.0 << copenhagen;
    QTest::newRow("NOAA 18, 10 degrees") << QStringLiteral("NOAA 18") << 10.0 << copenhagen;
    QTest::newRow("AO-91, equator") << QStringLiteral("FOX-1B (AO-91)") << 5.0 << quito;
    QTest::newRow("Molniya 1-53") << QStringLiteral("MOLNIYA 1-53") << 0.0 << copenhagen;
}

void TestPasses::matchesBruteForce()
{
    QFETCH(QString, satellite);
    QFETCH(double, minElevation);
    QFETCH(Site, station);
    const QList<ElementSet> sets = snapshot();
    const ElementSet *tle = named(sets, satellite);
    QVERIFY2(tle, qPrintable(satellite));
    const Sgp4 sat(*tle);
    // Twelve hours from the set's epoch, rounded to a minute.
    const double start = std::floor(sat.epochJulian() * kMinutesPerDay) / kMinutesPerDay;
    const PassWindow window{start, start + 0.5, minElevation};

    const QList<Pass> predicted = predictPasses(sat, station, window);
    const QList<BrutePass> brute = bruteForce(sat, station, window);
    QVERIFY(!brute.isEmpty());
    // The brute force stops at the window's end; the prediction follows a
    // pass past it. Compare the passes both see whole.
    QList<Pass> whole;
    for (const Pass &p : predicted)
        if (p.los.julian < window.endJulian)
            whole.append(p);
    QCOMPARE(whole.size(), brute.size());
    double worstAos = 0, worstLos = 0, worstPeak = 0;
    for (int i = 0; i < brute.size(); ++i) {
        const double dAos = std::fabs(whole[i].aos.julian - brute[i].aos) * kSecondsPerDay;
        const double dLos = std::fabs(whole[i].los.julian - brute[i].los) * kSecondsPerDay;
        worstAos = std::max(worstAos, dAos);
        worstLos = std::max(worstLos, dLos);
        worstPeak = std::max(worstPeak, std::fabs(whole[i].maxElevationDeg() - brute[i].maxElevation));
        QVERIFY2(dAos < 1.0, qPrintable(QStringLiteral("pass %1: AOS %2 s from the scan").arg(i).arg(dAos)));
        QVERIFY2(dLos < 1.0, qPrintable(QStringLiteral("pass %1: LOS %2 s from the scan").arg(i).arg(dLos)));
        // The peak is found to half a second, where the elevation is flat.
        QVERIFY(std::fabs(whole[i].maxElevationDeg() - brute[i].maxElevation) < 0.001);
        QVERIFY(whole[i].tca.julian >= whole[i].aos.julian && whole[i].tca.julian <= whole[i].los.julian);
    }
    qInfo("%s: %d passes, AOS worst %.3f s, LOS worst %.3f s, peak worst %.5f deg from the 0.1 s scan",
          qPrintable(satellite), int(brute.size()), worstAos, worstLos, worstPeak);
}

void TestPasses::allSatellitesSortedByAos()
{
    const QList<ElementSet> sets = snapshot();
    QList<ElementSet> some;
    for (const QString &name : {QStringLiteral("ISS (ZARYA)"), QStringLiteral("NOAA 18"), QStringLiteral("FOX-1B")})
        some.append(*named(sets, name));
    const Site station{55.6875, 12.625, 20, {}, {}};
    const double start = std::floor(Sgp4(some[0]).epochJulian());
    const PassWindow window{start, start + 1.0, 0.0};
    const QList<Pass> all = predictPasses(some, station, window);
    int total = 0;
    for (const ElementSet &t : some)
        total += predictPasses(Sgp4(t), station, window).size();
    QCOMPARE(all.size(), total);
    QSet<int> numbers;
    for (int i = 0; i < all.size(); ++i) {
        numbers.insert(all[i].catalogueNumber);
        if (i > 0)
            QVERIFY(all[i - 1].aos.julian <= all[i].aos.julian);
        QVERIFY(!all[i].name.isEmpty());
    }
    QCOMPARE(numbers.size(), 3);
}

void TestPasses::searchEndsOnAnyInput()
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    int calls = 0;
    const ElevationFunction sine = [&calls](double t) {
        ++calls;
        return ElevationSample{10.0 * std::sin(kTwoPi * t), 0.0};
    };
    PassScan scan;
    // A window that is not a number: the loop's time became NaN and its end
    // test was never true.
    for (const PassWindow &w : {PassWindow{nan, 1.0, 5.0}, PassWindow{0.0, nan, 5.0}, PassWindow{0.0, 1.0, nan},
                                PassWindow{0.0, inf, 5.0}, PassWindow{-inf, 1.0, 5.0}}) {
        calls = 0;
        QVERIFY(scanPasses(sine, w, scan).isEmpty());
        QVERIFY2(calls < 2, "nothing is computed for a window that is not a number");
    }
    PassScan nanScan;
    nanScan.maxElevationRateDegS = nan;
    QVERIFY(scanPasses(sine, {0.0, 1.0, 5.0}, nanScan).isEmpty());

    // An elevation that stops being a number (a satellite decayed in the
    // model): what was found before stands, and the search ends.
    const ElevationFunction failsLater = [nan](double t) {
        return ElevationSample{t < 0.6 ? 10.0 * std::sin(kTwoPi * t) : nan, 0.0};
    };
    const QList<Pass> before = scanPasses(failsLater, {0.0, 3.0, 5.0}, scan);
    QCOMPARE(before.size(), 1);

    // A stop from another thread ends a long search at its next step.
    std::atomic<bool> stop{false};
    calls = 0;
    const ElevationFunction stopsItself = [&](double t) {
        if (++calls == 100)
            stop = true;
        return ElevationSample{10.0 * std::sin(kTwoPi * t), 0.0};
    };
    PassWindow month{0.0, 30.0, 5.0};
    month.stop = &stop;
    scanPasses(stopsItself, month, scan);
    QVERIFY2(calls < 120, qPrintable(QString::number(calls)));

    // An elevation function that lies about its rate bound cannot hold the
    // search longer than the window's length allows.
    calls = 0;
    const ElevationFunction flat = [&calls](double) {
        ++calls;
        return ElevationSample{-90.0, 0.0, 0.0};
    };
    QVERIFY(scanPasses(flat, {0.0, 1.0, 5.0}, scan).isEmpty());
    QVERIFY2(calls <= 86400 / 15 + 20, qPrintable(QString::number(calls)));
}

void TestPasses::decayedSatelliteHasNoPasses()
{
    // The verification set's sub-orbital case (decayed 2005-11-29).
    ElementSet tle;
    ElementSetRefusal r;
    QVERIFY(parseTle(QStringLiteral("1 28872U 05037B   05333.02012661  .25992681  00000-0  24476-3 0  1534"),
                     QStringLiteral("2 28872  96.4736 157.9986 0303955 244.0492 110.6523 16.46015938 10708"), &tle,
                     &r, false));
    const Sgp4 sat(tle);
    const QList<Pass> passes = predictPasses(sat, Site{0, 0, 0, {}, {}}, {sat.epochJulian() + 1, sat.epochJulian() + 2, 0});
    QVERIFY(passes.isEmpty());
}

void TestPasses::sunAndMoonAgreeWithPyEphem()
{
    const Site station{51.4779, -0.0015, 46, {}, {}};
    const double start = 2460481.5; // 2024-06-20 00:00 UTC
    const PassWindow window{start, start + 3.0, kRiseSetElevationDeg};

    const char *script = R"(
import sys, math, ephem
o = ephem.Observer()
o.lat, o.lon, o.elevation = math.radians(51.4779), math.radians(-0.0015), 46
o.pressure = 0
o.horizon = '-0:50'
for body in (ephem.Sun(), ephem.Moon()):
    o.date = ephem.Date(2460481.5 - 2415020.0)
    for i in range(3):
        r = o.next_rising(body, use_center=True)
        t = o.next_transit(body, start=r)
        s = o.next_setting(body, start=r, use_center=True)
        o.date = t
        body.compute(o)
        print('%.8f %.8f %.8f %.6f' % (r + 2415020.0, t + 2415020.0, s + 2415020.0, math.degrees(body.alt)))
        o.date = s
)";
    QProcess ephem;
    ephem.start(kPython, {QStringLiteral("-c"), QString::fromLatin1(script)});
    QVERIFY(ephem.waitForFinished(60000));
    if (ephem.exitCode() != 0)
        QFAIL("python3 could not run PyEphem: install the Debian package python3-ephem");
    const QList<QByteArray> lines = ephem.readAllStandardOutput().trimmed().split('\n');
    QCOMPARE(lines.size(), 6);

    int line = 0;
    for (SkyBody body : {SkyBody::Sun, SkyBody::Moon}) {
        QList<Pass> passes = predictBodyPasses(body, station, window);
        passes.erase(std::remove_if(passes.begin(), passes.end(), [](const Pass &p) { return p.aosClipped; }),
                     passes.end());
        QVERIFY(passes.size() >= 3);
        for (int i = 0; i < 3; ++i, ++line) {
            const QList<QByteArray> f = lines[line].split(' ');
            const double dRise = std::fabs(passes[i].aos.julian - f[0].toDouble()) * kSecondsPerDay;
            const double dTransit = std::fabs(passes[i].tca.julian - f[1].toDouble()) * kSecondsPerDay;
            const double dSet = std::fabs(passes[i].los.julian - f[2].toDouble()) * kSecondsPerDay;
            const double dPeak = std::fabs(passes[i].maxElevationDeg() - f[3].toDouble());
            qInfo("%s %d: rise %.1f s, culmination %.1f s (%.4f deg), set %.1f s from PyEphem",
                  body == SkyBody::Sun ? "sun" : "moon", i, dRise, dTransit, dPeak, dSet);
            // 0.05° of position is 12 s of rise time at London's latitude.
            QVERIFY(dRise < 20.0);
            QVERIFY(dSet < 20.0);
            // Slew's culmination is the highest point, PyEphem's transit the
            // meridian crossing: the same for the sun, minutes apart for the
            // moon, whose declination changes fast. The heights agree.
            QVERIFY(dTransit < (body == SkyBody::Sun ? 30.0 : 600.0));
            QVERIFY(dPeak < 0.05);
        }
    }
}

QTEST_GUILESS_MAIN(TestPasses)
#include "tst_passes.moc"
