// SPDX-License-Identifier: GPL-3.0-or-later
// The station's horizon mask: the file (comments, walls, every refusal
// naming the file and the line, a device or a huge file refused), reading it
// between its points round through north, and passes that rise and set on
// it: AOS and LOS moved to where the satellite clears what hides the sky,
// at the satellite's own elevation there, and a pass that never clears it
// gone.

#include "sky/tleformat.h"
#include "sky/horizonmask.h"
#include "sky/passes.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace slew::sky;

namespace {

QList<ElementSet> snapshot()
{
    QFile file(QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle"));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return readTleText(QString::fromLatin1(file.readAll())).sets;
}

std::shared_ptr<const HorizonMask> maskOf(const QString &text)
{
    const HorizonFile read = parseHorizonText(text, QStringLiteral("test.horizon"));
    if (!read.mask)
        qWarning("%s", qPrintable(read.error));
    return read.mask;
}

// JO65hq, the station of the rehearsals.
Site copenhagen()
{
    Site s;
    QString error;
    parseSite(QStringLiteral("JO65hq"), &s, &error);
    return s;
}

} // namespace

class HorizonMaskTest : public QObject {
    Q_OBJECT
private slots:
    void readsPointsCommentsAndWalls()
    {
        const auto mask = maskOf(QStringLiteral("# the barn to the south-east\n"
                                                "0 5\n"
                                                "120  5   # its foot\n"
                                                "120 18\n"
                                                "150,18\n"
                                                "150 5\n"
                                                "\n"
                                                "300 -2\n"));
        QVERIFY(mask);
        QCOMPARE(mask->points().size(), 6);
        QCOMPARE(mask->elevationAt(60), 5.0);
        QCOMPARE(mask->elevationAt(120), 18.0); // on the wall: its top
        QCOMPARE(mask->elevationAt(135), 18.0);
        QCOMPARE(mask->elevationAt(119.999), 5.0 + 0.0);
        QCOMPARE(mask->elevationAt(225), 1.5); // halfway from 5° at 150° to -2° at 300°
        // Round through north: from -2° at 300° to 5° at 0°, and bearings past a turn.
        QCOMPARE(mask->elevationAt(330), 1.5);
        QCOMPARE(mask->elevationAt(330 + 360), 1.5);
        QCOMPARE(mask->elevationAt(-30), 1.5);
        QCOMPARE(mask->lowestDeg(), -2.0);
        QCOMPARE(mask->highestDeg(), 18.0);
        QCOMPARE(mask->describe(), QStringLiteral("6 points, -2.0° to 18.0° (highest at 120.0°)"));
        // Not a number: the whole mask's worst, never a NaN.
        QCOMPARE(mask->elevationAt(std::nan("")), 18.0);

        const auto flat = maskOf(QStringLiteral("360 3\n"));
        QVERIFY(flat);
        QCOMPARE(flat->elevationAt(0), 3.0);
        QCOMPARE(flat->elevationAt(271), 3.0);
    }

    void refusesWithTheFileAndTheLine_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("message");
        QTest::newRow("empty") << "# nothing\n\n" << "test.horizon: no points";
        QTest::newRow("one number") << "0 5\n90\n" << "test.horizon:2: expected `azimuth elevation`";
        QTest::newRow("three numbers") << "0 5 7\n" << "test.horizon:1: expected `azimuth elevation`";
        QTest::newRow("nan") << "0 5\n90 nan\n" << "test.horizon:2: elevation 'nan' is not a finite number";
        QTest::newRow("inf azimuth") << "inf 5\n" << "test.horizon:1: azimuth 'inf' is not a finite number";
        QTest::newRow("huge") << "0 1e999\n" << "test.horizon:1: elevation '1e999' is not a finite number";
        QTest::newRow("azimuth past a turn") << "361 5\n" << "test.horizon:1: azimuth 361° is outside 0..360°";
        QTest::newRow("elevation past the zenith") << "10 91\n" << "test.horizon:1: elevation 91° is outside -5..90°";
        QTest::newRow("below the ground") << "10 -6\n" << "test.horizon:1: elevation -6° is outside -5..90°";
        QTest::newRow("three at one azimuth") << "10 0\n10 5\n10 9\n"
                                              << "test.horizon: three points at azimuth 10°";
        QTest::newRow("words") << "north 5\n" << "test.horizon:1: azimuth 'north' is not a number";
    }

    void refusesWithTheFileAndTheLine()
    {
        QFETCH(QString, text);
        QFETCH(QString, message);
        const HorizonFile read = parseHorizonText(text, QStringLiteral("test.horizon"));
        QVERIFY(!read.mask);
        QVERIFY2(read.error.startsWith(message), qPrintable(read.error));
    }

    void readsOnlyARegularFileUnderItsCap()
    {
        QTemporaryDir dir;
        const QString good = dir.filePath(QStringLiteral("good.horizon"));
        QFile file(good);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("0 2\n180 12\n");
        file.close();
        const HorizonFile read = readHorizonFile(good);
        QVERIFY2(read.mask, qPrintable(read.error));
        QCOMPARE(read.mask->elevationAt(90), 7.0);

        const HorizonFile device = readHorizonFile(QStringLiteral("/dev/zero"));
        QVERIFY(!device.mask);
        QVERIFY2(device.error.contains(QStringLiteral("not a file")), qPrintable(device.error));
        QVERIFY(!readHorizonFile(dir.path()).mask);
        QVERIFY(!readHorizonFile(dir.filePath(QStringLiteral("missing"))).mask);

        const QString big = dir.filePath(QStringLiteral("big.horizon"));
        QFile huge(big);
        QVERIFY(huge.open(QIODevice::WriteOnly));
        huge.write(QByteArray(2 * 1024 * 1024, '#'));
        huge.close();
        const HorizonFile tooBig = readHorizonFile(big);
        QVERIFY(!tooBig.mask);
        QVERIFY2(tooBig.error.contains(QStringLiteral("1 MiB")), qPrintable(tooBig.error));
    }

    void passesRiseAndSetOnTheMask()
    {
        const QList<ElementSet> sets = snapshot();
        const QList<const ElementSet *> found = findSatellites(sets, QStringLiteral("NOAA 18"));
        QVERIFY(!found.isEmpty());
        const Sgp4 noaa(*found.first());
        const double start = std::floor(noaa.epochJulian()) + 0.5;
        const PassWindow window{start, start + 1.0, 0.0};
        Site flat = copenhagen();
        const QList<Pass> open = predictPasses(noaa, flat, window);
        QVERIFY(open.size() >= 4);

        // A ridge of 10° all round: every pass starts later and ends sooner,
        // at 10°, and the low ones are gone.
        Site ridge = flat;
        ridge.horizon = maskOf(QStringLiteral("0 10\n"));
        const QList<Pass> masked = predictPasses(noaa, ridge, window);
        int higher = 0;
        for (const Pass &p : open)
            higher += p.maxElevationDeg() > 10.0 ? 1 : 0;
        QCOMPARE(masked.size(), higher);
        const PassWindow tenDegrees{start, start + 1.0, 10.0};
        const QList<Pass> sameByMinimum = predictPasses(noaa, flat, tenDegrees);
        QCOMPARE(sameByMinimum.size(), masked.size());
        for (int i = 0; i < masked.size(); ++i) {
            QVERIFY(std::abs(masked[i].aos.julian - sameByMinimum[i].aos.julian) * kSecondsPerDay < 1.0);
            QVERIFY(std::abs(masked[i].los.julian - sameByMinimum[i].los.julian) * kSecondsPerDay < 1.0);
            QVERIFY(std::abs(masked[i].aos.elevationDeg - 10.0) < 0.05);
            QVERIFY(std::abs(masked[i].maxElevationDeg() - sameByMinimum[i].maxElevationDeg()) < 0.01);
        }

        // A wall of 30° only across the bearing where the highest pass rises:
        // its AOS moves to where it clears the wall, at the satellite's own
        // elevation there (above 30°, beside it the mask is 0°); its LOS
        // does not move.
        const Pass *high = &open.first();
        for (const Pass &p : open)
            if (p.maxElevationDeg() > high->maxElevationDeg())
                high = &p;
        const double rise = high->aos.azimuthDeg;
        auto at = [](double az) { return std::fmod(az + 360.0, 360.0); };
        Site walled = flat;
        walled.horizon = maskOf(QStringLiteral("%1 0\n%1 30\n%2 30\n%2 0\n")
                                    .arg(at(rise - 15), 0, 'f', 3)
                                    .arg(at(rise + 15), 0, 'f', 3));
        QVERIFY(walled.horizon);
        const QList<Pass> behindWall = predictPasses(noaa, walled, window);
        const Pass *moved = nullptr;
        for (const Pass &p : behindWall)
            if (std::abs(p.los.julian - high->los.julian) * kSecondsPerDay < 1.0)
                moved = &p;
        QVERIFY(moved);
        QVERIFY2((moved->aos.julian - high->aos.julian) * kSecondsPerDay > 60.0,
                 qPrintable(QString::number((moved->aos.julian - high->aos.julian) * kSecondsPerDay)));
        QVERIFY(moved->aos.elevationDeg >= 29.9 || std::abs(at(moved->aos.azimuthDeg - rise)) > 14.9);
        QVERIFY(std::abs(moved->maxElevationDeg() - high->maxElevationDeg()) < 0.01);
        // The other passes, rising elsewhere, are as before.
        QVERIFY(behindWall.size() >= open.size() - 1);
    }

    void aFixedDirectionBehindTheMaskHasNoPass()
    {
        // (tracking::TargetSky reads the same mask for a fixed target; see
        // tst_tracktarget.) Here: the sun behind a ridge higher than it
        // ever climbs on a winter's day has no pass at all.
        Site s = copenhagen();
        s.horizon = maskOf(QStringLiteral("0 80\n"));
        const double start = 2458140.5; // 2018-01-22 00:00 UTC
        const PassWindow window{start, start + 1.0, 0.0};
        QVERIFY(!predictBodyPasses(SkyBody::Sun, copenhagen(), window).isEmpty());
        QVERIFY(predictBodyPasses(SkyBody::Sun, s, window).isEmpty());
    }
};

QTEST_GUILESS_MAIN(HorizonMaskTest)
#include "tst_horizonmask.moc"
