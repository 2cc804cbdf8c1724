// SPDX-License-Identifier: GPL-3.0-or-later
// Sun and moon alignment (tracking/skyalignment.h): the offsets that turn the
// controller's reading into where the body is seen, across north, over the
// top, for an azimuth-only rotator, and the refusals.

#include "sky/utctime.h"
#include "tracking/skyalignment.h"

#include <QTest>

#include <cmath>

using namespace slew;
using namespace slew::tracking;

namespace {

const sky::Site kCopenhagen{55.7, 12.6, 10, {}, {}};
const sky::Site kSvalbard{78.2, 15.6, 10, {}, {}};

double at(const char *iso)
{
    return *sky::julianFromIso(QString::fromLatin1(iso));
}

double apparentElevation(const sky::BodyPosition &p)
{
    return p.elevationDeg + refractionDeg(p.elevationDeg);
}

} // namespace

class SkyAlignmentTest : public QObject {
    Q_OBJECT
private slots:
    void refraction()
    {
        QVERIFY(std::abs(refractionDeg(0.0) - 0.48) < 0.01);   // half a degree at the horizon
        QVERIFY(std::abs(refractionDeg(30.0) - 0.028) < 0.002);
        QVERIFY(refractionDeg(90.0) < 0.001);
        QCOMPARE(refractionDeg(-5.0), 0.0);
    }

    void offsetsPointTheReadingAtTheSun()
    {
        const double jd = at("2026-06-21T10:00:00Z");
        const sky::BodyPosition sun = sky::sunPosition(kCopenhagen, jd);
        QVERIFY(sun.elevationDeg > 30);
        const Alignment a = alignOn(sky::SkyBody::Sun, kCopenhagen, jd, sun.azimuthDeg - 3.0,
                                    apparentElevation(sun) + 1.25);
        QVERIFY2(a.ok(), qPrintable(a.refusal));
        QVERIFY(std::abs(a.azOffsetDeg - 3.0) < 1e-9);
        QVERIFY(std::abs(a.elOffsetDeg + 1.25) < 1e-9);
        QCOMPARE(a.bodyAzimuthDeg, sun.azimuthDeg);
    }

    void acrossNorth()
    {
        // The midnight sun seen from Svalbard, just east of north: a reading
        // 7° west of it is just west of north, and the offset is +7°, not -353°.
        double jd = at("2026-06-21T18:00:00Z");
        sky::BodyPosition sun;
        for (int minutes = 0; minutes < 12 * 60; ++minutes, jd += 1.0 / 1440.0) {
            sun = sky::sunPosition(kSvalbard, jd);
            if (sun.azimuthDeg > 1.0 && sun.azimuthDeg < 6.0)
                break;
        }
        QVERIFY(sun.azimuthDeg > 1.0 && sun.azimuthDeg < 6.0);
        const double reading = sun.azimuthDeg - 7.0 + 360.0;
        const Alignment east = alignOn(sky::SkyBody::Sun, kSvalbard, jd, reading, apparentElevation(sun));
        QVERIFY2(east.ok(), qPrintable(east.refusal));
        QVERIFY(std::abs(east.azOffsetDeg - 7.0) < 1e-9);
        // And a reading just east of north, the sun just west of it (-7°).
        const Alignment west = alignOn(sky::SkyBody::Sun, kSvalbard, jd, sun.azimuthDeg + 7.0, apparentElevation(sun));
        QVERIFY(std::abs(west.azOffsetDeg + 7.0) < 1e-9);
    }

    void overTheTop()
    {
        // A flipped antenna (elevation past 90°) points at the opposite azimuth.
        const double jd = at("2026-06-21T10:00:00Z");
        const sky::BodyPosition sun = sky::sunPosition(kCopenhagen, jd);
        const double el = apparentElevation(sun);
        const Alignment a = alignOn(sky::SkyBody::Sun, kCopenhagen, jd, sun.azimuthDeg + 180.0 + 2.0, 180.0 - el - 0.5);
        QVERIFY2(a.ok(), qPrintable(a.refusal));
        QVERIFY(std::abs(a.azOffsetDeg + 2.0) < 1e-9);
        QVERIFY(std::abs(a.elOffsetDeg - 0.5) < 1e-9);
    }

    void theMoon()
    {
        double jd = at("2026-11-01T00:00:00Z");
        sky::BodyPosition moon;
        for (int hours = 0; hours < 24 * 30; ++hours, jd += 1.0 / 24.0) {
            moon = sky::moonPosition(kCopenhagen, jd);
            if (moon.elevationDeg > 20)
                break;
        }
        QVERIFY(moon.elevationDeg > 20);
        const Alignment a = alignOn(sky::SkyBody::Moon, kCopenhagen, jd, moon.azimuthDeg + 1.5, apparentElevation(moon));
        QVERIFY2(a.ok(), qPrintable(a.refusal));
        QVERIFY(std::abs(a.azOffsetDeg + 1.5) < 1e-9);
        QVERIFY(std::abs(a.elOffsetDeg) < 1e-9);
    }

    void azimuthOnly()
    {
        const double jd = at("2026-06-21T10:00:00Z");
        const sky::BodyPosition sun = sky::sunPosition(kCopenhagen, jd);
        const Alignment a = alignOn(sky::SkyBody::Sun, kCopenhagen, jd, sun.azimuthDeg - 4.0, 0.0, false);
        QVERIFY2(a.ok(), qPrintable(a.refusal));
        QVERIFY(std::abs(a.azOffsetDeg - 4.0) < 1e-9);
        QCOMPARE(a.elOffsetDeg, 0.0);
    }

    void refusals()
    {
        const double night = at("2026-12-21T23:00:00Z");
        const Alignment low = alignOn(sky::SkyBody::Sun, kCopenhagen, night, 0, 10);
        QVERIFY(!low.ok());
        QVERIFY2(low.refusal.contains(QStringLiteral("too low")), qPrintable(low.refusal));
        const double day = at("2026-06-21T10:00:00Z");
        const sky::BodyPosition sun = sky::sunPosition(kCopenhagen, day);
        const Alignment far = alignOn(sky::SkyBody::Sun, kCopenhagen, day, sun.azimuthDeg, apparentElevation(sun) - 30);
        QVERIFY(!far.ok());
        QVERIFY2(far.refusal.contains(QStringLiteral("is the antenna on the sun")), qPrintable(far.refusal));
        QVERIFY(!alignOn(sky::SkyBody::Sun, kCopenhagen, day, qQNaN(), 10).ok());
    }
};

QTEST_MAIN(SkyAlignmentTest)
#include "tst_skyalignment.moc"
