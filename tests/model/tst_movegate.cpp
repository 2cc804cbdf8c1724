// SPDX-License-Identifier: GPL-3.0-or-later
// The gate every move passes: the profile's limits narrowed by the link's,
// bearings through the overlap, mechanical positions taken as they are,
// drives refused at the limit they push against, and refusals that name the
// limits that refused.

#include "model/movegate.h"

#include <QTest>

#include <cmath>
#include <limits>

using slew::model::MoveCheck;
using slew::model::MoveGate;
using slew::model::RotatorLimits;

namespace {
const RotatorLimits kOverlap{0.0, 450.0, 0.0, 90.0};
const RotatorLimits kPlain{0.0, 360.0, 0.0, 90.0};
const RotatorLimits kLinkReports{10.0, 350.0, 0.0, 80.0};
} // namespace

class MoveGateTest : public QObject {
    Q_OBJECT
private slots:
    void theLinkNarrowsTheProfile()
    {
        const MoveGate gate(kOverlap, kLinkReports);
        const RotatorLimits l = gate.limits();
        QCOMPARE(l.azMin, 10.0);
        QCOMPARE(l.azMax, 350.0);
        QCOMPARE(l.elMin, 0.0);
        QCOMPARE(l.elMax, 80.0);
        QCOMPARE(MoveGate(kPlain).limits().azMax, 360.0);
    }

    void refusalsNameTheLimitsThatRefused()
    {
        const MoveGate gate(kPlain, kLinkReports);
        const MoveCheck profile = gate.pointing(100, 95, std::nullopt);
        QVERIFY(!profile.allowed());
        QVERIFY2(!profile.refusal.contains(QStringLiteral("link")), qPrintable(profile.refusal));
        const MoveCheck link = gate.pointing(100, 85, std::nullopt);
        QVERIFY2(link.refusal.contains(QStringLiteral("elevation 85.0° is outside"))
                     && link.refusal.contains(QStringLiteral("the limits the link reports")),
                 qPrintable(link.refusal));
        QVERIFY(gate.pointing(355, 10, std::nullopt).refusal.contains(QStringLiteral("link reports")));
    }

    void bearingsChooseWithinTheNarrowedLimits()
    {
        // 370 would be the shorter way from 365 on the profile's 450°, but
        // the link allows 0..360 only: 10 it is, not a refusal.
        const MoveGate gate(kOverlap, RotatorLimits{0.0, 360.0, 0.0, 90.0});
        const MoveCheck c = gate.pointing(10, 20, 355.0);
        QVERIFY2(c.allowed(), qPrintable(c.refusal));
        QCOMPARE(c.azimuth, 10.0);
        QCOMPARE(c.elevation, 20.0);
        // Without the link's limits the overlap is used.
        QCOMPARE(MoveGate(kOverlap).pointing(10, 20, 355.0).azimuth, 370.0);
    }

    void positionsAreTakenAsTheyAre()
    {
        const MoveGate overlap(kOverlap);
        QCOMPARE(overlap.azimuthPosition(370).azimuth, 370.0);
        QCOMPARE(overlap.azimuthPosition(10).azimuth, 10.0); // not moved to 370 from anywhere
        // A south stop: -10 is a position, 350 is not (it would be a bearing).
        const MoveGate south(RotatorLimits{-180.0, 180.0, 0.0, 90.0});
        QVERIFY(south.azimuthPosition(-10).allowed());
        QVERIFY(!south.azimuthPosition(350).allowed());
        QCOMPARE(south.azimuthBearing(350, std::nullopt).azimuth, -10.0);
        QVERIFY(south.mechanical(-10, 45).allowed());
        QVERIFY(!south.mechanical(-10, 95).allowed());
    }

    void drivesStopAtTheLimitTheyPushAgainst()
    {
        const MoveGate gate(kPlain, kLinkReports);
        QVERIFY(!gate.drive(true, true, 350.0).allowed());
        QVERIFY(gate.drive(true, false, 350.0).allowed());
        QVERIFY(!gate.drive(true, false, 10.0).allowed());
        QVERIFY(!gate.drive(false, true, 80.0).allowed());
        QVERIFY(gate.drive(false, true, 79.0).allowed());
        QVERIFY(gate.drive(true, true, std::nullopt).allowed()); // nothing known to refuse on
        QVERIFY(gate.drive(true, true, 350.0).refusal.contains(QStringLiteral("upper limit (350.0°)")));
    }

    void nonsenseIsRefused()
    {
        const MoveGate gate(kPlain);
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const double inf = std::numeric_limits<double>::infinity();
        QVERIFY(!gate.pointing(nan, 10, std::nullopt).allowed());
        QVERIFY(!gate.pointing(10, nan, std::nullopt).allowed());
        QVERIFY(!gate.azimuthPosition(inf).allowed());
        QVERIFY(!gate.elevation(-inf).allowed());
        QVERIFY(!gate.pointing(1e300, 10, std::nullopt).allowed());
    }
};

QTEST_GUILESS_MAIN(MoveGateTest)
#include "tst_movegate.moc"
