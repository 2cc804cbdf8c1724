// SPDX-License-Identifier: GPL-3.0-or-later
// Transponders: the uplink that pairs with a downlink on a linear
// transponder, and the set by satellite and its default.

#include "radio/transponder.h"
#include "radio/transponderset.h"

#include <QTest>

#include <cmath>
#include <limits>

using namespace slew::radio;

namespace {

// A linear transponder like FO-29's: 145.900-146.000 MHz up, 435.800-435.900
// MHz down, inverting.
Transponder invertingLinear()
{
    Transponder t;
    t.noradId = 24278;
    t.description = QStringLiteral("Mode V/U linear");
    t.uplinkLowHz = 145.900e6;
    t.uplinkHighHz = 146.000e6;
    t.downlinkLowHz = 435.800e6;
    t.downlinkHighHz = 435.900e6;
    t.mode = QStringLiteral("SSB");
    t.inverting = true;
    return t;
}

// Like AO-7's mode A: 145.850-145.950 MHz up, 29.400-29.500 MHz down, not
// inverting.
Transponder nonInvertingLinear()
{
    Transponder t;
    t.noradId = 7530;
    t.description = QStringLiteral("Mode A linear");
    t.uplinkLowHz = 145.850e6;
    t.uplinkHighHz = 145.950e6;
    t.downlinkLowHz = 29.400e6;
    t.downlinkHighHz = 29.500e6;
    t.mode = QStringLiteral("SSB");
    return t;
}

Transponder beacon(int norad, double hz, const QString &description = QStringLiteral("beacon"))
{
    Transponder t;
    t.noradId = norad;
    t.description = description;
    t.downlinkLowHz = hz;
    t.mode = QStringLiteral("CW");
    return t;
}

} // namespace

class TestTransponders : public QObject {
    Q_OBJECT
private slots:
    // The value
    void linearMeansAPassbandOnTheDownlink();
    void uplinkForDownlinkInverting();
    void uplinkForDownlinkNotInverting();
    void noPairingOutsideThePassband_data();
    void noPairingOutsideThePassband();
    void downlinkForUplinkIsTheInverse();

    // The set
    void setKeepsEachSatellitesTransponders();
    void mergeDropsRepeatsAcrossSources();
    void defaultIsTheFirstAliveLinear();

};

// ---- The value ---------------------------------------------------------

void TestTransponders::linearMeansAPassbandOnTheDownlink()
{
    QVERIFY(invertingLinear().isLinear());
    QVERIFY(nonInvertingLinear().isLinear());
    QVERIFY(!beacon(24278, 435.795e6).isLinear());
    Transponder same = beacon(24278, 435.795e6);
    same.downlinkHighHz = 435.795e6;
    QVERIFY(!same.isLinear());
    // A passband on the uplink alone is not a linear transponder.
    Transponder uplinkOnly;
    uplinkOnly.uplinkLowHz = 145.9e6;
    uplinkOnly.uplinkHighHz = 146.0e6;
    QVERIFY(!uplinkOnly.isLinear());
}

void TestTransponders::uplinkForDownlinkInverting()
{
    const Transponder t = invertingLinear();
    // The middle maps to the middle; the bottom of the downlink to the top of
    // the uplink, and the other way round.
    QCOMPARE(t.uplinkForDownlink(435.850e6).value(), 145.950e6);
    QCOMPARE(t.uplinkForDownlink(435.800e6).value(), 146.000e6);
    QCOMPARE(t.uplinkForDownlink(435.900e6).value(), 145.900e6);
    QCOMPARE(t.uplinkForDownlink(435.810e6).value(), 145.990e6);
}

void TestTransponders::uplinkForDownlinkNotInverting()
{
    const Transponder t = nonInvertingLinear();
    QCOMPARE(t.uplinkForDownlink(29.450e6).value(), 145.900e6);
    QCOMPARE(t.uplinkForDownlink(29.400e6).value(), 145.850e6);
    QCOMPARE(t.uplinkForDownlink(29.500e6).value(), 145.950e6);
}

void TestTransponders::noPairingOutsideThePassband_data()
{
    QTest::addColumn<Transponder>("transponder");
    QTest::addColumn<double>("downlinkHz");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    QTest::newRow("below the passband") << invertingLinear() << 435.7999e6;
    QTest::newRow("above the passband") << invertingLinear() << 435.9001e6;
    QTest::newRow("nan") << invertingLinear() << nan;
    QTest::newRow("inf") << invertingLinear() << inf;
    QTest::newRow("-inf") << nonInvertingLinear() << -inf;
    QTest::newRow("a beacon") << beacon(24278, 435.795e6) << 435.795e6;
    Transponder noUplink = invertingLinear();
    noUplink.uplinkLowHz.reset();
    noUplink.uplinkHighHz.reset();
    QTest::newRow("no uplink") << noUplink << 435.85e6;
}

void TestTransponders::noPairingOutsideThePassband()
{
    QFETCH(Transponder, transponder);
    QFETCH(double, downlinkHz);
    QVERIFY(!transponder.uplinkForDownlink(downlinkHz));
}

void TestTransponders::downlinkForUplinkIsTheInverse()
{
    for (const Transponder &t : {invertingLinear(), nonInvertingLinear()}) {
        for (double f = *t.downlinkLowHz; f <= *t.downlinkHighHz; f += 10e3) {
            const std::optional<double> up = t.uplinkForDownlink(f);
            QVERIFY(up);
            QVERIFY(std::abs(t.downlinkForUplink(*up).value() - f) < 1e-3);
        }
        QVERIFY(!t.downlinkForUplink(*t.uplinkLowHz - 1e3));
        QVERIFY(!t.downlinkForUplink(*t.uplinkHighHz + 1e3));
        QVERIFY(!t.downlinkForUplink(std::numeric_limits<double>::quiet_NaN()));
    }
}

// ---- The set -----------------------------------------------------------

void TestTransponders::setKeepsEachSatellitesTransponders()
{
    TransponderSet set;
    QVERIFY(set.isEmpty());
    QCOMPARE(set.merge({beacon(24278, 435.795e6), invertingLinear(), nonInvertingLinear()}), 0);
    QCOMPARE(set.size(), 3);
    QCOMPARE(set.satellites(), (QList<int>{7530, 24278}));
    const QList<Transponder> fo29 = set.forSatellite(24278);
    QCOMPARE(fo29.size(), 2);
    QCOMPARE(fo29[0].description, QStringLiteral("beacon"));
    QCOMPARE(fo29[1].description, QStringLiteral("Mode V/U linear"));
    QVERIFY(set.forSatellite(25544).isEmpty());
}

void TestTransponders::mergeDropsRepeatsAcrossSources()
{
    TransponderSet set;
    Transponder fromSatnogs = invertingLinear();
    fromSatnogs.uuid = QStringLiteral("SlwTest000000000000001");
    QCOMPARE(set.merge({fromSatnogs}), 0);

    // The same entry again (a second copy of the list), with a changed
    // description: the one held stays.
    Transponder again = fromSatnogs;
    again.description = QStringLiteral("renamed");
    // The same transponder from a Gpredict file: no uuid, the same
    // frequencies, sense and mode in other letter case.
    Transponder fromGpredict = invertingLinear();
    fromGpredict.mode = QStringLiteral("ssb");
    fromGpredict.description = QStringLiteral("[Mode V/U linear]");
    // Not the same: another mode on the same frequencies, another satellite.
    Transponder otherMode = invertingLinear();
    otherMode.mode = QStringLiteral("CW");
    Transponder otherSatellite = invertingLinear();
    otherSatellite.noradId = 44909;
    QCOMPARE(set.merge({again, fromGpredict, otherMode, otherSatellite}), 2);
    QCOMPARE(set.size(), 3);
    QCOMPARE(set.forSatellite(24278).size(), 2);
    QCOMPARE(set.forSatellite(24278)[0].description, QStringLiteral("Mode V/U linear"));
    QCOMPARE(set.forSatellite(44909).size(), 1);
}

void TestTransponders::defaultIsTheFirstAliveLinear()
{
    Transponder deadLinear = nonInvertingLinear();
    deadLinear.noradId = 24278;
    deadLinear.alive = false;
    Transponder deadBeacon = beacon(24278, 435.795e6, QStringLiteral("dead beacon"));
    deadBeacon.alive = false;

    TransponderSet set;
    // The linear comes after a beacon and a dead linear, and still wins.
    set.merge({deadBeacon, beacon(24278, 435.796e6, QStringLiteral("alive beacon")), deadLinear, invertingLinear()});
    QCOMPARE(set.defaultFor(24278)->description, QStringLiteral("Mode V/U linear"));

    // No alive linear: the first alive of any kind.
    TransponderSet noLinear;
    noLinear.merge({deadBeacon, deadLinear, beacon(24278, 435.796e6, QStringLiteral("alive beacon"))});
    QCOMPARE(noLinear.defaultFor(24278)->description, QStringLiteral("alive beacon"));

    // Nothing alive: no default; an unknown satellite: none either.
    TransponderSet dead;
    dead.merge({deadBeacon, deadLinear});
    QVERIFY(!dead.defaultFor(24278));
    QVERIFY(!set.defaultFor(25544));
}

QTEST_GUILESS_MAIN(TestTransponders)
#include "tst_transponders.moc"
