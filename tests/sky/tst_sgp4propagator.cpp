// SPDX-License-Identifier: GPL-3.0-or-later
// Sgp4Propagator carries the resonance integration of 12-hour and 24-hour
// orbits from one call to the next; the states must be those of integrating
// from epoch every time, whatever order the times come in. The resonant sets
// are taken from the published verification set (SGP4-VER.TLE, shipped by
// Debian's python3-sgp4 and read from there, as tst_sgp4verification does).

#include "sky/tleformat.h"
#include "sky/sgp4.h"
#include "sky/sgp4propagator.h"
#include "sky/elementsetformat.h"

#include <QFile>
#include <QRandomGenerator>
#include <QTest>

#include <limits>

#include <cmath>

using namespace slew::sky;

namespace {

const QString kVerificationSet = QStringLiteral("/usr/lib/python3/dist-packages/sgp4/SGP4-VER.TLE");

// Half-day (Molniya) and one-day (geosynchronous) resonances: 08195 is
// Molniya 2-14, 14128 is EUTELSAT 1-F1, 09998 a geosynchronous set with a
// drift of 0.16 turns a day.
const QList<int> kResonantSets = {8195, 21897, 14128, 9998};

// The integrator's half-day step, in minutes.
constexpr double kStep = 720.0;

QList<ElementSet> resonantSets()
{
    QFile f(kVerificationSet);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    QList<ElementSet> found;
    const QStringList lines = QString::fromLatin1(f.readAll()).split(u'\n');
    for (int i = 0; i + 1 < lines.size(); ++i) {
        if (!lines[i].startsWith(u'1') || !lines[i + 1].startsWith(u'2'))
            continue;
        ElementSet tle;
        ElementSetRefusal refusal;
        // The file's lines carry start, stop and step after column 69.
        if (parseTle(lines[i].left(69), lines[i + 1].left(69), &tle, &refusal, false)
            && kResonantSets.contains(tle.catalogueNumber))
            found.append(tle);
    }
    return found;
}

// The times a caller might ask in one run: forward, backward towards and
// across epoch, on and either side of the step points, and jumping about.
QList<double> askedTimes()
{
    QList<double> times;
    for (double t = 0; t <= 5 * 1440.0; t += 17.3) // forward over five days
        times.append(t);
    for (double t = 5 * 1440.0; t >= -3 * 1440.0; t -= 41.9) // back across epoch
        times.append(t);
    for (double t = -3 * 1440.0; t >= -6 * 1440.0; t -= 29.0) // on away from it, before
        times.append(t);
    for (int k = -12; k <= 12; ++k) // exactly on, and just either side of, step points
        for (double d : {0.0, -1e-9, 1e-9, -0.5, 0.5})
            times.append(k * kStep + d);
    times.append(0.0);
    QRandomGenerator random(27); // the same jumps every run, so a failure can be replayed
    for (int i = 0; i < 400; ++i)
        times.append((random.generateDouble() * 2.0 - 1.0) * 30 * 1440.0);
    for (int i = 0; i < 200; ++i) // small jumps around one spot, as a crossing search makes
        times.append(10 * 1440.0 + (random.generateDouble() - 0.5) * 3 * kStep);
    return times;
}

double difference(const Sgp4State &a, const Sgp4State &b)
{
    return std::max((a.positionKm - b.positionKm).norm(), (a.velocityKmS - b.velocityKmS).norm());
}

} // namespace

class TestSgp4Propagator : public QObject {
    Q_OBJECT
private slots:
    void carriedIntegrationMatchesFromEpoch();
    void propagatorsOfOneSetAreIndependent();
    void aTimeThatIsNoTimeIsRefusedAtOnce();
};

void TestSgp4Propagator::aTimeThatIsNoTimeIsRefusedAtOnce()
{
    // The resonance integration steps half a day at a time: an infinite or
    // absurd time once looped for ever. Now each is refused, carried or not.
    const QList<ElementSet> sets = resonantSets();
    QVERIFY(!sets.isEmpty());
    const Sgp4 sgp4(sets.first());
    Sgp4Propagator carried(sgp4);
    for (double t : {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                     std::numeric_limits<double>::quiet_NaN(), 1e300, -1e300, 101 * 365.25 * 1440.0}) {
        QCOMPARE(int(sgp4.propagate(t).error), int(Sgp4Error::TimeOutOfRange));
        QCOMPARE(int(carried.propagate(t).error), int(Sgp4Error::TimeOutOfRange));
    }
    // A century is still a time, and the carried state still agrees after.
    QVERIFY(sgp4.propagate(99 * 365.25 * 1440.0).error != Sgp4Error::TimeOutOfRange);
    QVERIFY(difference(carried.propagate(720.0), sgp4.propagate(720.0)) <= 1e-9);
}

void TestSgp4Propagator::carriedIntegrationMatchesFromEpoch()
{
    const QList<ElementSet> sets = resonantSets();
    if (sets.isEmpty())
        QFAIL(qPrintable(kVerificationSet + QStringLiteral(" is missing: install the Debian package python3-sgp4")));
    QCOMPARE(sets.size(), kResonantSets.size());

    const QList<double> times = askedTimes();
    double worst = 0;
    for (const ElementSet &tle : sets) {
        const Sgp4 sgp4(tle);
        QVERIFY(sgp4.isDeepSpace());
        Sgp4Propagator carried(sgp4);
        for (double t : times) {
            const Sgp4State fromEpoch = sgp4.propagate(t);
            const Sgp4State s = carried.propagate(t);
            QCOMPARE(int(s.error), int(fromEpoch.error));
            if (!fromEpoch.ok())
                continue;
            const double d = difference(s, fromEpoch);
            worst = std::max(worst, d);
            QVERIFY2(d <= 1e-9, qPrintable(QStringLiteral("%1 at %2 min: %3 km (or km/s) from the state "
                                                          "integrated from epoch")
                                               .arg(tle.catalogueNumber)
                                               .arg(t, 0, 'f', 6)
                                               .arg(d)));
        }
    }
    qInfo("%d resonant sets at %d times: worst difference %g km", int(sets.size()), int(times.size()), worst);
}

void TestSgp4Propagator::propagatorsOfOneSetAreIndependent()
{
    // Two callers on one Sgp4 (the planner's worker and the window's tick),
    // one going forward, one back: neither disturbs the other, as the
    // state is theirs, not the Sgp4's.
    const QList<ElementSet> sets = resonantSets();
    QVERIFY(!sets.isEmpty());
    const Sgp4 sgp4(sets.first());
    Sgp4Propagator forward(sgp4), backward(sgp4);
    for (int i = 0; i < 200; ++i) {
        const double ahead = i * 37.0, behind = -i * 53.0;
        QVERIFY(difference(forward.propagate(ahead), sgp4.propagate(ahead)) <= 1e-9);
        QVERIFY(difference(backward.propagate(behind), sgp4.propagate(behind)) <= 1e-9);
    }
    QCOMPARE(&forward.satellite(), &sgp4);
}

QTEST_GUILESS_MAIN(TestSgp4Propagator)
#include "tst_sgp4propagator.moc"
