// SPDX-License-Identifier: GPL-3.0-or-later
// The sun and the moon from libnova against an independent ephemeris:
// PyEphem (Debian's python3-ephem, built on XEphem's libastro, which shares
// no code with libnova), run as a real process. Apparent topocentric
// positions without refraction, for stations around the world over several
// decades, must agree within 0.05°.

#include "sky/sunmoon.h"

#include <QProcess>
#include <QRandomGenerator>
#include <QTest>

#include <algorithm>

using namespace slew::sky;

namespace {

const QString kPython = QStringLiteral("/usr/bin/python3");

// PyEphem dates count days from 1899 December 31 12:00 (JD 2415020.0).
const char *kEphemScript = R"(
import sys, math, ephem
for line in sys.stdin:
    lat, lon, h, jd = (float(x) for x in line.split())
    o = ephem.Observer()
    o.lat, o.lon, o.elevation = math.radians(lat), math.radians(lon), h
    o.pressure = 0
    o.date = ephem.Date(jd - 2415020.0)
    out = []
    for body in (ephem.Sun(), ephem.Moon()):
        body.compute(o)
        out += [math.degrees(body.az), math.degrees(body.alt)]
    print(*('%.9f' % x for x in out))
)";

double separationDeg(double az1, double el1, double az2, double el2)
{
    const double a1 = radians(az1), e1 = radians(el1), a2 = radians(az2), e2 = radians(el2);
    const double c = std::sin(e1) * std::sin(e2) + std::cos(e1) * std::cos(e2) * std::cos(a1 - a2);
    return degrees(std::acos(std::clamp(c, -1.0, 1.0)));
}

struct Case {
    Site station;
    double jd;
};

} // namespace

class TestSunMoon : public QObject {
    Q_OBJECT
private slots:
    void agreesWithPyEphem();
    void sunVectorPointsAtTheSun();
};

void TestSunMoon::agreesWithPyEphem()
{
    QList<Case> cases;
    // Fixed cases a person can check: noon in Greenwich at the June
    // solstice, a southern station, the poles, a mountain.
    cases.append({{51.4779, -0.0015, 46, {}, {}}, 2460482.0});
    cases.append({{-33.9, 18.4, 120, {}, {}}, 2451545.0});
    cases.append({{89.9, 0, 0, {}, {}}, 2455000.25});
    cases.append({{-89.9, 0, 2835, {}, {}}, 2458000.75});
    cases.append({{19.82, -155.47, 4200, {}, {}}, 2461000.1});
    QRandomGenerator random(12);
    while (cases.size() < 400) {
        const Site s{degrees(std::asin(random.generateDouble() * 2 - 1)), random.generateDouble() * 360 - 180,
                     random.generateDouble() * 3000, {}, {}};
        // 1980..2040
        cases.append({s, 2444239.5 + random.generateDouble() * 60 * 365.25});
    }
    QByteArray input;
    for (const Case &c : cases)
        input += QByteArray::number(c.station.latitudeDeg, 'g', 12) + ' '
                 + QByteArray::number(c.station.longitudeDeg, 'g', 12) + ' '
                 + QByteArray::number(c.station.heightM, 'g', 12) + ' ' + QByteArray::number(c.jd, 'f', 8) + '\n';

    QProcess ephem;
    ephem.start(kPython, {QStringLiteral("-c"), QString::fromLatin1(kEphemScript)});
    QVERIFY(ephem.waitForStarted(30000));
    ephem.write(input);
    ephem.closeWriteChannel();
    QVERIFY(ephem.waitForFinished(120000));
    if (ephem.exitCode() != 0)
        QFAIL(qPrintable(QStringLiteral("python3 could not run PyEphem: install the Debian package python3-ephem (%1)")
                             .arg(QString::fromLocal8Bit(ephem.readAllStandardError()).trimmed())));
    const QList<QByteArray> answers = ephem.readAllStandardOutput().trimmed().split('\n');
    QCOMPARE(answers.size(), cases.size());

    double worstSun = 0, worstMoon = 0;
    QList<double> sunErrors, moonErrors;
    for (int i = 0; i < cases.size(); ++i) {
        const QList<QByteArray> f = answers[i].split(' ');
        QCOMPARE(f.size(), 4);
        const BodyPosition sun = sunPosition(cases[i].station, cases[i].jd);
        const BodyPosition moon = moonPosition(cases[i].station, cases[i].jd);
        const double dSun = separationDeg(sun.azimuthDeg, sun.elevationDeg, f[0].toDouble(), f[1].toDouble());
        const double dMoon = separationDeg(moon.azimuthDeg, moon.elevationDeg, f[2].toDouble(), f[3].toDouble());
        sunErrors.append(dSun);
        moonErrors.append(dMoon);
        worstSun = std::max(worstSun, dSun);
        worstMoon = std::max(worstMoon, dMoon);
        QVERIFY2(dSun < 0.05, qPrintable(QStringLiteral("sun, case %1: %2° from PyEphem").arg(i).arg(dSun)));
        QVERIFY2(dMoon < 0.05, qPrintable(QStringLiteral("moon, case %1: %2° from PyEphem").arg(i).arg(dMoon)));
    }
    std::sort(sunErrors.begin(), sunErrors.end());
    std::sort(moonErrors.begin(), moonErrors.end());
    qInfo("libnova against PyEphem, %d cases: sun median %.4f° worst %.4f°; moon median %.4f° worst %.4f°",
          int(cases.size()), sunErrors[sunErrors.size() / 2], worstSun, moonErrors[moonErrors.size() / 2], worstMoon);
}

void TestSunMoon::sunVectorPointsAtTheSun()
{
    // At the March equinox of 2024 (20 March 03:06 UTC) the sun is at
    // right ascension 0, declination 0, 0.996 AU away.
    const Vec3 sun = sunVectorEquatorial(2460389.629);
    QVERIFY(std::fabs(sun.norm() / 149597870.7 - 0.996) < 0.001);
    QVERIFY(std::fabs(degrees(std::asin(sun.z / sun.norm()))) < 0.01);
    QVERIFY(std::fabs(degrees(std::atan2(sun.y, sun.x))) < 0.02);
}

QTEST_GUILESS_MAIN(TestSunMoon)
#include "tst_sunmoon.moc"
