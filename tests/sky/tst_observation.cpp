// SPDX-License-Identifier: GPL-3.0-or-later
// The station (coordinates and Maidenhead locators, with their refusals),
// sidereal time, the Earth-fixed frame, look angles, Doppler, refraction,
// the sub-satellite point and the shadow test, as tables of inputs and
// answers worked by hand or taken from published examples.

#include "sky/observation.h"
#include "sky/sgp4.h"
#include "sky/site.h"

#include <QTest>

using namespace slew::sky;

Q_DECLARE_METATYPE(slew::sky::Site)

class TestObservation : public QObject {
    Q_OBJECT
private slots:
    void stations_data();
    void stations();
    void refusedStations_data();
    void refusedStations();
    void locatorOfAPosition();
    void siderealTime();
    void lookAngles_data();
    void lookAngles();
    void rangeRateAndDoppler();
    void geodeticRoundTrip();
    void refraction();
    void shadow_data();
    void shadow();
};

void TestObservation::stations_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<double>("lat");
    QTest::addColumn<double>("lon");
    QTest::addColumn<double>("height");
    QTest::newRow("lat,lon") << QStringLiteral("55.6875,12.625") << 55.6875 << 12.625 << 0.0;
    QTest::newRow("lat,lon,height") << QStringLiteral(" -33.9, 18.4 , 120") << -33.9 << 18.4 << 120.0;
    QTest::newRow("east longitude past 180") << QStringLiteral("40,300") << 40.0 << -60.0 << 0.0;
    // Locator centres, worked by hand from the field/square/subsquare sizes.
    QTest::newRow("JO65 square") << QStringLiteral("JO65") << 55.5 << 13.0 << 0.0;
    QTest::newRow("JO65hq subsquare") << QStringLiteral("JO65hq") << 55.6875 << 12.625 << 0.0;
    QTest::newRow("lower case") << QStringLiteral("jo65HQ") << 55.6875 << 12.625 << 0.0;
    QTest::newRow("FN31pr (ARRL)") << QStringLiteral("FN31pr") << 41.729166666 << -72.708333333 << 0.0;
    // JO65hq starts at 12.5833°E 55.6667°N; extended squares are 0.5′ × 0.25′.
    QTest::newRow("8 characters") << QStringLiteral("JO65hq42") << 55.677083333 << 12.620833333 << 0.0;
    QTest::newRow("south-west corner") << QStringLiteral("AA00aa") << -90.0 + 1.25 / 60.0 << -180.0 + 2.5 / 60.0
                                       << 0.0;
}

void TestObservation::stations()
{
    QFETCH(QString, text);
    QFETCH(double, lat);
    QFETCH(double, lon);
    QFETCH(double, height);
    Site s;
    QString error;
    QVERIFY2(parseSite(text, &s, &error), qPrintable(error));
    QVERIFY2(std::fabs(s.latitudeDeg - lat) < 1e-6, qPrintable(QString::number(s.latitudeDeg, 'f', 9)));
    QVERIFY2(std::fabs(s.longitudeDeg - lon) < 1e-6, qPrintable(QString::number(s.longitudeDeg, 'f', 9)));
    QCOMPARE(s.heightM, height);
}

void TestObservation::refusedStations_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("reasonContains");
    QTest::newRow("empty") << QString() << QStringLiteral("no station");
    QTest::newRow("3 characters") << QStringLiteral("JO6") << QStringLiteral("4, 6 or 8");
    QTest::newRow("7 characters") << QStringLiteral("JO65hq4") << QStringLiteral("4, 6 or 8");
    QTest::newRow("field beyond R") << QStringLiteral("ZZ00") << QStringLiteral("letters A to R");
    QTest::newRow("subsquare beyond X") << QStringLiteral("JO65hz") << QStringLiteral("letters A to X");
    QTest::newRow("letter for digit") << QStringLiteral("JOx5") << QStringLiteral("digits");
    QTest::newRow("latitude 91") << QStringLiteral("91,0") << QStringLiteral("latitude");
    QTest::newRow("not numbers") << QStringLiteral("north,10") << QStringLiteral("must be finite numbers");
    QTest::newRow("too many fields") << QStringLiteral("1,2,3,4") << QStringLiteral("LAT,LON");
    QTest::newRow("height in the sky") << QStringLiteral("10,10,50000") << QStringLiteral("height");
}

void TestObservation::refusedStations()
{
    QFETCH(QString, text);
    QFETCH(QString, reasonContains);
    Site s;
    QString error;
    QVERIFY(!parseSite(text, &s, &error));
    QVERIFY2(error.contains(reasonContains), qPrintable(error));
}

void TestObservation::locatorOfAPosition()
{
    QCOMPARE(siteLocator(55.6875, 12.625), QStringLiteral("JO65hq"));
    QCOMPARE(siteLocator(41.7147, -72.7272), QStringLiteral("FN31pr"));
    QCOMPARE(siteLocator(-90.0, -180.0), QStringLiteral("AA00aa"));
}

void TestObservation::siderealTime()
{
    // Vallado, "Fundamentals of Astrodynamics and Applications", example
    // 3-5: 1992 August 20, 12:14 UT1 has GMST 152.578787810°.
    const double jd = 2448855.009722222;
    QVERIFY2(std::fabs(degrees(gmstIau82(jd)) - 152.578787810) < 1e-5,
             qPrintable(QString::number(degrees(gmstIau82(jd)), 'f', 9)));
}

void TestObservation::lookAngles_data()
{
    QTest::addColumn<Site>("station");
    QTest::addColumn<double>("x");
    QTest::addColumn<double>("y");
    QTest::addColumn<double>("z");
    QTest::addColumn<double>("az");
    QTest::addColumn<double>("el");
    QTest::addColumn<double>("range");
    const Site origin{0, 0, 0, {}, {}};
    const double r = 6378.137;
    QTest::newRow("overhead") << origin << r + 1000 << 0.0 << 0.0 << -1.0 << 90.0 << 1000.0;
    QTest::newRow("due east on the horizon") << origin << r << 1000.0 << 0.0 << 90.0 << 0.0 << 1000.0;
    QTest::newRow("due north on the horizon") << origin << r << 0.0 << 1000.0 << 0.0 << 0.0 << 1000.0;
    QTest::newRow("due west, 45 up") << origin << r + 1000 << -1000.0 << 0.0 << 270.0 << 45.0 << std::sqrt(2.0) * 1000;
    QTest::newRow("pole, south at 45") << Site{90, 0, 0, {}, {}} << 1000.0 << 0.0 << 6356.752314 + 1000 << 180.0 << 45.0
                                        << std::sqrt(2.0) * 1000;
}

void TestObservation::lookAngles()
{
    QFETCH(Site, station);
    QFETCH(double, x);
    QFETCH(double, y);
    QFETCH(double, z);
    QFETCH(double, az);
    QFETCH(double, el);
    QFETCH(double, range);
    const LookAngles look = lookAnglesEarthFixed(station, {x, y, z}, {});
    if (az >= 0)
        QVERIFY2(std::fabs(look.azimuthDeg - az) < 1e-6, qPrintable(QString::number(look.azimuthDeg)));
    QVERIFY2(std::fabs(look.elevationDeg - el) < 1e-6, qPrintable(QString::number(look.elevationDeg)));
    QVERIFY2(std::fabs(look.rangeKm - range) < 1e-6, qPrintable(QString::number(look.rangeKm)));
}

void TestObservation::rangeRateAndDoppler()
{
    const Site origin{0, 0, 0, {}, {}};
    // Overhead and climbing straight up at 7 km/s: receding at 7 km/s.
    const LookAngles away = lookAnglesEarthFixed(origin, {6378.137 + 500, 0, 0}, {7, 0, 0});
    QVERIFY(std::fabs(away.rangeRateKmS - 7.0) < 1e-12);
    // Moving across the line of sight: no range-rate.
    const LookAngles across = lookAnglesEarthFixed(origin, {6378.137 + 500, 0, 0}, {0, 7, 0});
    QVERIFY(std::fabs(across.rangeRateKmS) < 1e-12);
    // 437 MHz from a satellite receding at 7 km/s arrives 10.2 kHz low.
    QVERIFY(std::fabs(dopplerShiftHz(437e6, 7.0) - (-437e6 * 7.0 / 299792.458)) < 1e-6);
    QVERIFY(std::fabs(dopplerShiftHz(437e6, 7.0) + 10204.0) < 1.0);
    QCOMPARE(dopplerFactor(0.0), 1.0);

    // TEME velocity seen from the rotating earth: a point fixed over the
    // station in TEME appears to move west at ωr.
    const double jd = 2460000.5;
    const Vec3 v = temeVelocityToEarthFixed({42164, 0, 0}, {0, 0, 0}, jd);
    QVERIFY(std::fabs(v.norm() - kEarthRotationRadS * 42164) < 1e-9);
}

void TestObservation::geodeticRoundTrip()
{
    const Site s{45.0, 10.0, 500000.0, {}, {}};
    const Geodetic g = earthFixedToGeodetic(siteEarthFixed(s));
    QVERIFY(std::fabs(g.latitudeDeg - 45.0) < 1e-9);
    QVERIFY(std::fabs(g.longitudeDeg - 10.0) < 1e-9);
    QVERIFY(std::fabs(g.heightKm - 500.0) < 1e-6);

    // A TEME position at GMST 0 lies over longitude 0.
    const double jd = 2448855.009722222;
    const double g0 = gmstIau82(jd);
    const Geodetic under = subSatellitePoint({7000 * std::cos(g0), 7000 * std::sin(g0), 0}, jd);
    QVERIFY(std::fabs(under.longitudeDeg) < 1e-9);
    QVERIFY(std::fabs(under.latitudeDeg) < 1e-9);
    QVERIFY(std::fabs(under.heightKm - (7000 - 6378.137)) < 1e-6);
}

void TestObservation::refraction()
{
    // Sæmundsson's formula: 29′ at the horizon, 1′ at 45°, nothing overhead.
    QVERIFY(std::fabs(refractionDeg(0.0) * 60.0 - 28.98) < 0.05);
    QVERIFY(std::fabs(refractionDeg(45.0) * 60.0 - 1.0) < 0.05);
    QVERIFY(std::fabs(refractionDeg(90.0)) < 1e-4);
    QCOMPARE(refractionDeg(-5.0), 0.0);
}

void TestObservation::shadow_data()
{
    QTest::addColumn<double>("x");
    QTest::addColumn<double>("y");
    QTest::addColumn<bool>("sunlit");
    // The sun along +x; the earth's radius is 6378 km.
    QTest::newRow("day side") << 7000.0 << 0.0 << true;
    QTest::newRow("behind the earth") << -7000.0 << 0.0 << false;
    QTest::newRow("behind, beside the shadow") << -7000.0 << 6500.0 << true;
    QTest::newRow("behind, inside the shadow edge") << -7000.0 << 6300.0 << false;
    QTest::newRow("terminator") << 0.0 << 7000.0 << true;
}

void TestObservation::shadow()
{
    QFETCH(double, x);
    QFETCH(double, y);
    QFETCH(bool, sunlit);
    QCOMPARE(isSunlit({x, y, 0}, {1.5e8, 0, 0}), sunlit);
}

QTEST_GUILESS_MAIN(TestObservation)
#include "tst_observation.moc"
