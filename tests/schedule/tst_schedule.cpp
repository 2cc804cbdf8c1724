// SPDX-License-Identifier: GPL-3.0-or-later
// The schedule: priority wins an overlap, a pass the rotator cannot reach in
// time is dropped with that reason (a 360° rotator that must turn back
// between two passes, where a 450° one goes on through its overlap), a
// lower priority is not let in where it would leave a higher one out of
// reach, the horizon mask drops a pass that never clears it, old elements
// drop a pass, the sun is fitted into the gaps, a pass in progress is kept
// through a new plan, and the JSON says all of it.

#include "schedule/schedule.h"
#include "schedule/scheduletext.h"

#include "sky/passes.h"
#include "sky/sgp4.h"
#include "sky/tleformat.h"
#include "sky/elementsetformat.h"
#include "sky/utctime.h"

#include <QFile>
#include <QJsonArray>
#include <QTest>

#include <cmath>

using namespace slew::schedule;
using slew::tracking::RotatorReach;
using slew::tracking::SkyPoint;

namespace {

constexpr double kDay = 86400.0;
const double kStart = *slew::sky::julianFromIso(QStringLiteral("2018-01-22T08:00:00Z"));

RotatorReach rotator(double azMax, double elMax)
{
    RotatorReach r;
    r.limits.azMin = 0;
    r.limits.azMax = azMax;
    r.limits.elMin = 0;
    r.limits.elMax = elMax;
    r.azimuthRateDegS = 6.2; // a G-5500
    r.elevationRateDegS = 2.7;
    return r;
}

// A made-up pass: from `startMin` minutes after kStart for `minutes`, its
// bearing from az0 to az1 (the short way), up to `peak` degrees.
ScheduledPass madeUp(int priority, const QString &name, int norad, double startMin, double minutes, double az0,
                     double az1, double peak, const RotatorReach &reach)
{
    ScheduledPass p;
    p.priority = priority;
    p.target = name;
    p.norad = norad;
    p.startJulian = kStart + startMin * 60.0 / kDay;
    p.endJulian = p.startJulian + minutes * 60.0 / kDay;
    const double seconds = minutes * 60.0;
    for (double s = 0; s <= seconds + 1e-9; s += 10.0) {
        const double f = s / seconds;
        double az = az0 + f * std::remainder(az1 - az0, 360.0);
        az = std::fmod(az + 360.0, 360.0);
        p.points.append(SkyPoint{s, az, peak * std::sin(M_PI * f)});
    }
    p.pass.aos = {p.startJulian, az0, 0};
    p.pass.los = {p.endJulian, az1, 0};
    p.pass.tca = {(p.startJulian + p.endJulian) / 2, 0, peak};
    p.plan = slew::tracking::planPass(p.points, reach);
    p.first = {p.plan.path.front().azimuth, p.plan.path.front().elevation};
    p.last = {p.plan.path.back().azimuth, p.plan.path.back().elevation};
    p.predictedWorstDeg = p.plan.predictedWorstDeg;
    return p;
}

ScheduleSettings settingsFrom(double guardSeconds = 30)
{
    ScheduleSettings s;
    s.startJulian = kStart;
    s.hours = 24;
    s.guardSeconds = guardSeconds;
    return s;
}

const ScheduledPass *find(const Schedule &s, const QString &target)
{
    for (const ScheduledPass &p : s.passes)
        if (p.target == target)
            return &p;
    return nullptr;
}

QList<slew::sky::ElementSet> snapshot()
{
    QFile file(QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle"));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return slew::sky::readTleText(QString::fromLatin1(file.readAll())).sets;
}

slew::tracking::TrackTarget satellite(const QString &name)
{
    static const QList<slew::sky::ElementSet> sets = snapshot();
    slew::tracking::TrackTarget t;
    const QList<const slew::sky::ElementSet *> found = slew::sky::findSatellites(sets, name);
    if (!found.isEmpty())
        t.elements = *found.first();
    return t;
}

slew::sky::Site jo65hq()
{
    slew::sky::Site s;
    QString error;
    slew::sky::parseSite(QStringLiteral("JO65hq"), &s, &error);
    return s;
}

} // namespace

class ScheduleTest : public QObject {
    Q_OBJECT
private slots:
    void priorityWinsAnOverlap()
    {
        const RotatorReach reach = rotator(450, 180);
        const ScheduledPass a = madeUp(0, "A", 1, 60, 10, 200, 300, 40, reach);
        const ScheduledPass b = madeUp(1, "B", 2, 65, 10, 100, 10, 30, reach);
        Schedule s = arrangeSchedule({{a}, {b}}, reach, settingsFrom());
        QVERIFY(find(s, "A")->taken);
        QVERIFY(!find(s, "B")->taken);
        QCOMPARE(find(s, "B")->reason, DropReason::Overlap);
        QVERIFY2(find(s, "B")->why.startsWith("overlaps A (priority 1, 09:00:00–09:10:00 UTC)"),
                 qPrintable(find(s, "B")->why));
        // The other way round, the other one wins.
        ScheduledPass a2 = a, b2 = b;
        a2.priority = 1;
        b2.priority = 0;
        s = arrangeSchedule({{b2}, {a2}}, reach, settingsFrom());
        QVERIFY(find(s, "B")->taken);
        QCOMPARE(find(s, "A")->reason, DropReason::Overlap);
        // The guard time counts: 20 s apart is an overlap with 30 s of guard.
        const ScheduledPass c = madeUp(1, "C", 3, 70 + 20.0 / 60, 5, 300, 320, 10, reach);
        s = arrangeSchedule({{a}, {c}}, reach, settingsFrom(30));
        QCOMPARE(find(s, "C")->reason, DropReason::Overlap);
        s = arrangeSchedule({{a}, {c}}, reach, settingsFrom(10));
        QVERIFY(find(s, "C")->taken);
        QCOMPARE(s.takenCount(), 2);
    }

    void aPassTheRotatorCannotReachInTimeIsDropped()
    {
        // A leaves the antenna at 350°. B rises at 10°, 40 s later. A 360°
        // rotator must turn back through south, 340° at 6.2°/s: 55 s.
        const RotatorReach turnsBack = rotator(360, 90);
        const ScheduledPass a = madeUp(0, "A", 1, 60, 10, 290, 350, 40, turnsBack);
        const ScheduledPass b = madeUp(1, "B", 2, 70 + 40.0 / 60, 8, 10, 80, 30, turnsBack);
        QCOMPARE(a.last.azimuth, 350.0);
        QCOMPARE(b.first.azimuth, 10.0);
        Schedule s = arrangeSchedule({{a}, {b}}, turnsBack, settingsFrom(5));
        QVERIFY(find(s, "A")->taken);
        const ScheduledPass *dropped = find(s, "B");
        QCOMPARE(dropped->reason, DropReason::Unreachable);
        QVERIFY2(dropped->why.contains("the rotator cannot reach its AOS point (az 10.0°, el 0.0°) from where A "
                                       "(priority 1, 09:00:00–09:10:00 UTC) leaves it (az 350.0°, el 0.0°) in time: "
                                       "the move takes 55 s, and there are 35 s"),
                 qPrintable(dropped->why));
        // A 450° rotator goes on through its overlap: B planned from 350°
        // starts at 370°, 20° on.
        const RotatorReach overlap = rotator(450, 90);
        const ScheduledPass a4 = madeUp(0, "A", 1, 60, 10, 290, 350, 40, overlap);
        const ScheduledPass b4 = madeUp(1, "B", 2, 70 + 40.0 / 60, 8, 10, 80, 30, overlap);
        s = arrangeSchedule({{a4}, {b4}}, overlap, settingsFrom(5));
        QVERIFY2(find(s, "B")->taken, qPrintable(find(s, "B")->why));
        QVERIFY(std::abs(find(s, "B")->first.azimuth - 370.0) < 0.5);

        // Nor is a lower priority let in where it would leave a higher one
        // out of reach: C (priority 3) between A and a B that starts later.
        const ScheduledPass bLater = madeUp(1, "B", 2, 73, 8, 10, 80, 30, turnsBack);
        const ScheduledPass c = madeUp(2, "C", 3, 70 + 40.0 / 60, 2, 170, 175, 5, turnsBack);
        s = arrangeSchedule({{a}, {bLater}, {c}}, turnsBack, settingsFrom(5));
        QVERIFY(find(s, "B")->taken);
        QCOMPARE(find(s, "C")->reason, DropReason::Unreachable);
        QVERIFY2(find(s, "C")->why.startsWith("taking it would leave the rotator"), qPrintable(find(s, "C")->why));

        // From where the antenna stands at the start.
        ScheduleSettings from = settingsFrom(5);
        from.antennaAt = AntennaPoint{0, 0};
        const ScheduledPass soon = madeUp(0, "Soon", 4, 0.25, 5, 180, 200, 20, turnsBack);
        s = arrangeSchedule({{soon}}, turnsBack, from);
        QCOMPARE(find(s, "Soon")->reason, DropReason::Unreachable);
        QVERIFY(find(s, "Soon")->why.contains("from where the antenna stands at the start (az 0.0°, el 0.0°)"));
    }

    void aPassInProgressIsKeptThroughANewPlan()
    {
        const RotatorReach reach = rotator(450, 180);
        ScheduledPass low = madeUp(3, "Low", 5, 60, 10, 100, 200, 20, reach);
        const ScheduledPass high = madeUp(0, "High", 6, 62, 10, 120, 220, 60, reach);
        // Planned afresh with the low-priority pass under way: it stays, and
        // the high one (which overlaps it) is the one dropped, saying why.
        const Schedule s = arrangeSchedule({{high}}, reach, settingsFrom(), {low});
        QVERIFY(find(s, "Low")->taken);
        QVERIFY(find(s, "Low")->pinned);
        QCOMPARE(find(s, "High")->reason, DropReason::Overlap);
        QVERIFY(describeScheduledPass(*find(s, "Low")).contains("in progress"));
    }

    void theHorizonMaskDropsAPassItHides()
    {
        // FLOCK 2P-1 from JO65hq on 2018-01-22, 07:00 to 13:00: passes of
        // 7.1°, 56.4°, 19.3° and 2.5°. A ridge of 15° all round hides the low
        // two; the others rise later and set sooner, on the ridge.
        ScheduleSettings settings = settingsFrom();
        settings.startJulian = *slew::sky::julianFromIso(QStringLiteral("2018-01-22T07:00:00Z"));
        settings.hours = 6;
        const QList<slew::tracking::TrackTarget> targets{satellite("FLOCK 2P-1")};
        QVERIFY(targets.first().elements.catalogueNumber != 0);
        const RotatorReach reach = rotator(450, 180);
        const Schedule open = planSchedule(targets, jo65hq(), reach, settings);
        slew::sky::Site ridge = jo65hq();
        ridge.horizon = slew::sky::parseHorizonText("0 15\n", "ridge").mask;
        const Schedule masked = planSchedule(targets, ridge, reach, settings);
        qInfo("open:\n%s\nmasked:\n%s", qPrintable(describeScheduleSummary(open)),
              qPrintable(describeScheduleSummary(masked)));
        int hidden = 0;
        for (const ScheduledPass &p : open.passes) {
            QVERIFY(p.taken);
            const auto same = std::find_if(masked.passes.begin(), masked.passes.end(), [&](const ScheduledPass &m) {
                return std::abs(m.pass.tca.julian - p.pass.tca.julian) * kDay < 60;
            });
            QVERIFY(same != masked.passes.end());
            if (p.pass.maxElevationDeg() < 15) {
                ++hidden;
                QVERIFY(!same->taken);
                QCOMPARE(same->reason, DropReason::BelowHorizon);
                QVERIFY2(same->why.startsWith("never clears the horizon mask: highest ")
                             && same->why.endsWith("where the mask is 15.0°"),
                         qPrintable(same->why));
            } else {
                QVERIFY(same->taken);
                QVERIFY((same->startJulian - p.startJulian) * kDay > 60); // rises later, on the ridge
                QVERIFY((p.endJulian - same->endJulian) * kDay > 60);
                QVERIFY(std::abs(same->pass.aos.elevationDeg - 15) < 0.1);
            }
        }
        QCOMPARE(hidden, 2);
    }

    void oldElementsDropAPass()
    {
        ScheduleSettings settings = settingsFrom();
        settings.hours = 4;
        settings.maxElementAgeDays = 0.01; // a quarter of an hour
        const Schedule s = planSchedule({satellite("FLOCK 2P-1")}, jo65hq(), rotator(450, 180), settings);
        QVERIFY(!s.passes.isEmpty());
        for (const ScheduledPass &p : s.passes) {
            QCOMPARE(p.reason, DropReason::StaleElements);
            QVERIFY2(p.why.contains("days from AOS (epoch 2018-01-2"), qPrintable(p.why));
        }
    }

    void theMinimumElevationFiltersPassesAndKeepsTheirAos()
    {
        // A pass is one thing everywhere: AOS and LOS at the horizon, as the
        // window's table and `slew --passes` give them. The schedule's
        // minimum elevation keeps the passes that climb to it, whole.
        ScheduleSettings settings = settingsFrom();
        settings.hours = 24;
        const slew::tracking::TrackTarget flock = satellite("FLOCK 2P-1");
        const slew::sky::PassWindow window{settings.startJulian, settings.startJulian + 1.0, 0.0};
        const QList<slew::sky::Pass> all = slew::sky::predictPasses(slew::sky::Sgp4(flock.elements), jo65hq(), window);
        settings.minElevationDeg = 30;
        const Schedule s = planSchedule({flock}, jo65hq(), rotator(450, 180), settings);
        QList<slew::sky::Pass> high;
        for (const slew::sky::Pass &p : all)
            if (p.maxElevationDeg() >= 30)
                high << p;
        QVERIFY(!high.isEmpty() && high.size() < all.size()); // some climb to 30°, some do not
        QCOMPARE(s.passes.size(), high.size());
        for (int i = 0; i < high.size(); ++i) {
            QCOMPARE(s.passes.at(i).pass.aos.julian, high.at(i).aos.julian);
            QCOMPARE(s.passes.at(i).pass.los.julian, high.at(i).los.julian);
            QCOMPARE(s.passes.at(i).startJulian, high.at(i).aos.julian); // tracked from the horizon
        }
    }

    void theSunFillsTheGaps()
    {
        // The sun second: its day, less FLOCK 2P-1's passes and a guard
        // either side and the moves, in pieces.
        ScheduleSettings settings = settingsFrom(30);
        settings.hours = 8;
        slew::tracking::TrackTarget sun;
        sun.kind = slew::tracking::TrackTarget::Kind::Sun;
        const Schedule s = planSchedule({satellite("FLOCK 2P-1"), sun}, jo65hq(), rotator(450, 180), settings);
        QList<const ScheduledPass *> flock, sunPieces;
        for (const ScheduledPass &p : s.passes) {
            if (!p.taken)
                continue;
            (p.target == sun.name() ? sunPieces : flock).append(&p);
        }
        QVERIFY(!flock.isEmpty());
        QVERIFY(sunPieces.size() >= 2);
        for (const ScheduledPass *f : flock)
            for (const ScheduledPass *piece : sunPieces)
                QVERIFY(piece->endJulian + 30 / kDay <= f->startJulian + 1e-9
                        || f->endJulian + 30 / kDay <= piece->startJulian + 1e-9);
        QVERIFY(sunPieces.first()->why.contains("between other passes"));
        for (const ScheduledPass *piece : sunPieces)
            QVERIFY(piece->durationSeconds() >= settings.shortestPieceSeconds);
    }

    void saysItInJson()
    {
        const RotatorReach reach = rotator(450, 180);
        const ScheduledPass a = madeUp(0, "A", 11, 60, 10, 200, 300, 40, reach);
        const ScheduledPass b = madeUp(1, "B", 12, 65, 10, 100, 10, 30, reach);
        Schedule s = arrangeSchedule({{a}, {b}}, reach, settingsFrom());
        s.targets = {"A", "B"};
        const QJsonObject json = scheduleToJson(s);
        QCOMPARE(json["taken"].toInt(), 1);
        QCOMPARE(json["dropped"].toInt(), 1);
        QCOMPARE(json["targets"].toArray().at(1).toObject()["name"].toString(), QStringLiteral("B"));
        const QJsonArray passes = json["passes"].toArray();
        QCOMPARE(passes.size(), 2);
        QCOMPARE(passes.at(0).toObject()["target"].toString(), QStringLiteral("A"));
        QCOMPARE(passes.at(0).toObject()["start"].toString(), QStringLiteral("2018-01-22T09:00:00.000Z"));
        QCOMPARE(passes.at(1).toObject()["reason"].toString(), QStringLiteral("overlap"));
        QCOMPARE(passes.at(1).toObject()["norad"].toInt(), 12);
        QVERIFY(passes.at(1).toObject()["why"].toString().startsWith("overlaps A"));
        QCOMPARE(describeScheduleSummary(s), QStringLiteral("1 pass taken, 1 dropped, 2018-01-22 08:00 to 2018-01-23 08:00 UTC"));
    }

    void refusesAWindowThatIsNotANumber()
    {
        ScheduleSettings settings = settingsFrom();
        settings.hours = std::nan("");
        const Schedule s = planSchedule({satellite("FLOCK 2P-1")}, jo65hq(), rotator(450, 180), settings);
        QVERIFY(s.passes.isEmpty());
        QCOMPARE(s.notes.size(), 1);
        settings.hours = 24 * 365;
        QVERIFY(planSchedule({satellite("FLOCK 2P-1")}, jo65hq(), rotator(450, 180), settings).passes.isEmpty());
    }
};

QTEST_GUILESS_MAIN(ScheduleTest)
#include "tst_schedule.moc"
