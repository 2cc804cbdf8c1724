// SPDX-License-Identifier: GPL-3.0-or-later
// Targets beyond satellites, the sun and the moon: a fixed azimuth and
// elevation, and a fixed point of the sky by J2000 right ascension and
// declination (tracking/tracktarget.h, sky/sunmoon.h celestialPosition).
// The sky positions are checked against geometry that does not depend on
// the code under test: the celestial pole stands at the station's latitude
// due north, a source culminates due south at 90° - latitude + declination,
// and it comes back to the same place after one sidereal day.

#include "sky/passes.h"
#include "sky/sunmoon.h"
#include "sky/utctime.h"
#include "tracking/tracktarget.h"

#include <QTest>

#include <cmath>

using namespace slew;
using tracking::TargetSky;
using tracking::TrackTarget;

namespace {

const sky::Site kStation{55.7, 12.6, 10, {}, {}};
constexpr double kSiderealDay = 0.99726957;

double at(const char *iso)
{
    return *sky::julianFromIso(QString::fromLatin1(iso));
}

} // namespace

class TrackTargetTest : public QObject {
    Q_OBJECT
private slots:
    void parses_data()
    {
        QTest::addColumn<QString>("spec");
        QTest::addColumn<int>("kind");
        QTest::addColumn<double>("a");
        QTest::addColumn<double>("b");
        QTest::newRow("azel") << "azel:123.5,41" << int(TrackTarget::Kind::Fixed) << 123.5 << 41.0;
        QTest::newRow("AZEL") << "AZEL:0,90" << int(TrackTarget::Kind::Fixed) << 0.0 << 90.0;
        QTest::newRow("hours") << "radec:12.5,-30" << int(TrackTarget::Kind::Celestial) << 187.5 << -30.0;
        // Cassiopeia A.
        QTest::newRow("sexagesimal") << "radec:23:23:24,+58:48:54" << int(TrackTarget::Kind::Celestial)
                                     << (23 + 23 / 60.0 + 24 / 3600.0) * 15 << 58 + 48 / 60.0 + 54 / 3600.0;
        QTest::newRow("h suffix") << "radec:5.5h,-5:30" << int(TrackTarget::Kind::Celestial) << 82.5 << -5.5;
        QTest::newRow("degrees") << "radec:350.85d,58.8" << int(TrackTarget::Kind::Celestial) << 350.85 << 58.8;
    }
    void parses()
    {
        QFETCH(QString, spec);
        QFETCH(int, kind);
        QFETCH(double, a);
        QFETCH(double, b);
        QString error;
        const auto t = TrackTarget::parseFixedOrCelestial(spec, &error);
        QVERIFY2(t, qPrintable(error));
        QCOMPARE(int(t->kind), kind);
        const bool fixed = t->kind == TrackTarget::Kind::Fixed;
        QVERIFY(std::abs((fixed ? t->azimuthDeg : t->rightAscensionDeg) - a) < 1e-9);
        QVERIFY(std::abs((fixed ? t->elevationDeg : t->declinationDeg) - b) < 1e-9);
    }

    void refuses_data()
    {
        QTest::addColumn<QString>("spec");
        QTest::addColumn<QString>("message");
        QTest::newRow("az 360") << "azel:360,10" << "azimuth 0..360";
        QTest::newRow("el 91") << "azel:10,91" << "elevation -5..90";
        QTest::newRow("one value") << "azel:10" << "azel:AZ,EL";
        QTest::newRow("ra 24h") << "radec:24,0" << "hours";
        QTest::newRow("ra degrees 360") << "radec:360d,0" << "hours";
        QTest::newRow("dec 91") << "radec:1,91" << "declination";
        QTest::newRow("minutes 60") << "radec:1:60:00,10" << "hours";
        QTest::newRow("words") << "radec:cas,a" << "hours";
    }
    void refuses()
    {
        QFETCH(QString, spec);
        QFETCH(QString, message);
        QString error;
        QVERIFY(!TrackTarget::parseFixedOrCelestial(spec, &error));
        QVERIFY2(error.contains(message), qPrintable(error));
    }

    void othersAreNotTaken()
    {
        QString error;
        QVERIFY(!TrackTarget::parseFixedOrCelestial(QStringLiteral("sun"), &error));
        QVERIFY(!TrackTarget::parseFixedOrCelestial(QStringLiteral("25544"), &error));
        QVERIFY(error.isEmpty());
    }

    void theCelestialPole()
    {
        // Precession has moved the pole of date about 0.15° from J2000's
        // since 2000; refraction is not included.
        const sky::BodyPosition p = sky::celestialPosition(0, 90, kStation, at("2026-11-23T12:00:00Z"));
        QVERIFY2(std::abs(p.elevationDeg - kStation.latitudeDeg) < 0.3, qPrintable(QString::number(p.elevationDeg)));
        QVERIFY(std::abs(std::remainder(p.azimuthDeg, 360.0)) < 0.5);
    }

    void culminatesDueSouth()
    {
        const double dec = 20.0;
        const QList<sky::Pass> passes = sky::predictCelestialPasses(
            100.0, dec, kStation, sky::PassWindow{at("2026-11-23T00:00:00Z"), at("2026-11-24T00:00:00Z"), 0.0});
        // The one that rises and sets inside the day (another may run over its ends).
        const auto whole = std::find_if(passes.begin(), passes.end(),
                                        [](const sky::Pass &p) { return !p.aosClipped && !p.losClipped; });
        QVERIFY(whole != passes.end());
        const sky::Pass &p = *whole;
        QVERIFY2(std::abs(p.tca.elevationDeg - (90 - kStation.latitudeDeg + dec)) < 0.5,
                 qPrintable(QString::number(p.tca.elevationDeg)));
        QVERIFY(std::abs(p.tca.azimuthDeg - 180) < 0.5);
        // Up from hour angle -H to +H, cos H = -tan(latitude) tan(declination):
        // 16.2 hours here. Precession since J2000 moves it by a minute or two.
        const double rad = M_PI / 180.0;
        const double hourAngle = std::acos(-std::tan(kStation.latitudeDeg * rad) * std::tan(dec * rad)) / rad;
        const double expected = 2 * hourAngle / 360.0 * kSiderealDay * 86400.0;
        QVERIFY2(std::abs(p.durationSeconds() - expected) < 300,
                 qPrintable(QStringLiteral("%1 s, expected %2 s").arg(p.durationSeconds()).arg(expected)));
    }

    void returnsAfterASiderealDay()
    {
        const double jd = at("2026-11-23T20:00:00Z");
        const sky::BodyPosition a = sky::celestialPosition(350.85, 58.8, kStation, jd);
        const sky::BodyPosition b = sky::celestialPosition(350.85, 58.8, kStation, jd + kSiderealDay);
        QVERIFY(std::abs(a.azimuthDeg - b.azimuthDeg) < 0.01 && std::abs(a.elevationDeg - b.elevationDeg) < 0.01);
        // Half a sidereal day later it is elsewhere.
        const sky::BodyPosition c = sky::celestialPosition(350.85, 58.8, kStation, jd + kSiderealDay / 2);
        QVERIFY(std::abs(a.elevationDeg - c.elevationDeg) > 10);
    }

    void aFixedDirectionIsOneLongPass()
    {
        TrackTarget t;
        t.kind = TrackTarget::Kind::Fixed;
        t.azimuthDeg = 200;
        t.elevationDeg = 30;
        TargetSky sky(t); // lookAt() carries state from call to call
        const sky::PassWindow window{2461000.5, 2461002.5, 0.0};
        const QList<sky::Pass> passes = sky.passes(kStation, window);
        QCOMPARE(passes.size(), 1);
        QCOMPARE(passes.first().aos.julian, window.startJulian);
        QCOMPARE(passes.first().los.julian, window.endJulian);
        const QList<tracking::SkyPoint> points = sky.sample(kStation, passes.first(), window.startJulian + 0.5);
        QVERIFY(points.size() > 2);
        for (const tracking::SkyPoint &p : points)
            QVERIFY(p.azimuthDeg == 200 && p.elevationDeg == 30);
        QVERIFY(sky.passes(kStation, sky::PassWindow{2461000.5, 2461002.5, 35.0}).isEmpty()); // below the minimum
        QCOMPARE(sky.lookAt(kStation, 2461001.0)->azimuthDeg, 200.0);
    }

    void theMoonSampledFromItsTheoryEveryTenMinutes()
    {
        // The theory every ten minutes and a straight line between: within a
        // thousandth of a degree of computing it at every point.
        TrackTarget t;
        t.kind = TrackTarget::Kind::Moon;
        const TargetSky sky(t);
        const double from = at("2026-11-23T00:00:00Z");
        const QList<sky::Pass> passes = sky.passes(kStation, sky::PassWindow{from, from + 1.0, 0.0});
        QVERIFY(!passes.isEmpty());
        const sky::Pass &p = passes.first();
        const QList<tracking::SkyPoint> points = sky.sample(kStation, p, p.aos.julian);
        QVERIFY(points.size() > 100);
        double worst = 0;
        for (const tracking::SkyPoint &point : points) {
            const sky::BodyPosition exact = sky::moonPosition(kStation, p.aos.julian + point.seconds / sky::kSecondsPerDay);
            worst = std::max({worst, std::abs(std::remainder(point.azimuthDeg - exact.azimuthDeg, 360.0)),
                              std::abs(point.elevationDeg - exact.elevationDeg)});
        }
        qInfo("worst difference %.6f° over %lld points", worst, (long long)points.size());
        QVERIFY(worst < 0.001);
    }

    void aSourceIsSampledAsItMoves()
    {
        const auto t = TrackTarget::parseFixedOrCelestial(QStringLiteral("radec:23:23:24,+58:48:54"), nullptr);
        const TargetSky sky(*t);
        const QList<sky::Pass> passes =
            sky.passes(kStation, sky::PassWindow{at("2026-11-23T00:00:00Z"), at("2026-11-24T00:00:00Z"), 10.0});
        QVERIFY(!passes.isEmpty());
        const sky::Pass &p = passes.first();
        const QList<tracking::SkyPoint> points = sky.sample(kStation, p, p.aos.julian);
        QVERIFY(points.size() > 100);
        const double jd = p.aos.julian + points[50].seconds / sky::kSecondsPerDay;
        const sky::BodyPosition truth = sky::celestialPosition(t->rightAscensionDeg, t->declinationDeg, kStation, jd);
        QVERIFY2(std::abs(points[50].azimuthDeg - truth.azimuthDeg) < 1e-6,
                 qPrintable(QStringLiteral("%1 %2").arg(points[50].azimuthDeg, 0, 'f', 9).arg(truth.azimuthDeg, 0, 'f', 9)));
    }
};

QTEST_MAIN(TrackTargetTest)
#include "tst_tracktarget.moc"
