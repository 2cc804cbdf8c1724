// SPDX-License-Identifier: GPL-3.0-or-later
// A day of an unattended station: five satellites in priority order over
// JO65hq, from the element sets in tests/data, on a simulated G-5500 class
// rotator (450°/180°, 6.2°/s azimuth, 2.7°/s elevation), on the
// simulator's manual clock.
//
//  - Slew's schedule (schedule/schedule.h): passes taken by priority, each
//    only where the rotator can get to it from the pass before; every
//    pass taken or dropped, and why. Then every taken pass followed in
//    turn on one simulated rotator, as the station service follows them
//    (the tracker pre-positions from where the last pass left the
//    antenna), with the pointing error the tracker measures.
//  - Gpredict-autotrack style on the same passes: whatever comes up next
//    once the pass being followed has set, with no priority and no thought
//    for whether the rotator can get there in time.
//
// For each it counts the passes of each priority the day had and those it
// lost, and for the autotrack style, how many of the passes it takes start
// out of the rotator's reach (the move from the last LOS takes longer than
// the time to AOS).

#include "common/simulatorpump.h"
#include "linkschemes.h"
#include "schedule/schedule.h"
#include "schedule/scheduletext.h"
#include "session/rotatorsession.h"
#include "sim/simulator.h"
#include "sky/tleformat.h"
#include "sky/elementsetformat.h"
#include "sky/utctime.h"
#include "tracking/rotatorreach.h"
#include "tracking/tracker.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>

#include <cmath>
#include <cstdio>
#include <map>

using namespace slew;
using schedule::ScheduledPass;

namespace {

const char *const kTargets[] = {"ISS (ZARYA)", "FOX-1B (AO-91)", "SAUDISAT 1C (SO-50)", "NOAA 19",
                                "FUNCUBE-1 (AO-73)"};
constexpr int kTargetCount = int(std::size(kTargets));
// The longest wait between two passes on the simulator: time enough to get
// anywhere; longer gaps are skipped, the antenna standing still in them.
constexpr double kLongestWaitS = 300.0;

sky::Site jo65hq()
{
    sky::Site s;
    QString error;
    sky::parseSite(QStringLiteral("JO65hq"), &s, &error);
    return s;
}

QList<tracking::TrackTarget> targets()
{
    QFile file(QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle"));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    const QList<sky::ElementSet> sets = sky::readTleText(QString::fromLatin1(file.readAll())).sets;
    QList<tracking::TrackTarget> out;
    for (const char *name : kTargets) {
        QString error;
        const sky::ElementSet *tle = sky::findOneSatellite(sets, QString::fromLatin1(name), &error);
        if (!tle) {
            std::printf("%s: %s\n", name, qPrintable(error));
            return {};
        }
        tracking::TrackTarget t;
        t.elements = *tle;
        out.append(t);
    }
    return out;
}

// Every pass of the day as a candidate, whatever the schedule made of it.
QList<ScheduledPass> everyPass(const schedule::Schedule &plan)
{
    QList<ScheduledPass> all = plan.passes;
    std::sort(all.begin(), all.end(),
              [](const ScheduledPass &a, const ScheduledPass &b) { return a.pass.aos.julian < b.pass.aos.julian; });
    return all;
}

struct Autotrack {
    QList<ScheduledPass> taken;
    int outOfReach = 0; // passes it starts that the rotator cannot reach by AOS
};

// Gpredict's autotrack: when nothing is followed, the next satellite to come
// up; followed to its LOS. No priority, no reach.
Autotrack autotrack(const QList<ScheduledPass> &passes, const tracking::RotatorReach &reach)
{
    Autotrack out;
    double busyUntil = -1;
    std::optional<schedule::AntennaPoint> antenna;
    for (const ScheduledPass &p : passes) {
        if (p.reason == schedule::DropReason::BelowHorizon || p.pass.aos.julian < busyUntil)
            continue;
        if (antenna && p.plan.isValid()) {
            const double gap = (p.pass.aos.julian - busyUntil) * sky::kSecondsPerDay;
            if (schedule::moveSeconds(reach, *antenna, p.first) > gap)
                ++out.outOfReach;
        }
        out.taken.append(p);
        busyUntil = p.pass.los.julian;
        if (p.plan.isValid())
            antenna = p.last;
    }
    return out;
}

// The taken passes followed in turn on one simulated rotator; the tracker's
// figures for each.
QList<tracking::TrackingFigures> follow(const QList<ScheduledPass> &taken, double *simulatedSeconds)
{
    session::RotatorSession session;
    model::RotatorProfile profile;
    profile.limits = model::RotatorLimits{0, 450, 0, 180};
    profile.parkAz = 0;
    profile.parkEl = 0;
    session.setProfile(profile);
    session.connectTo(QStringLiteral("sim:?clock=manual&az_max=450&el_max=180"));
    SimulatorPump pump{0.02};
    pump.follow(&session);
    runEventLoopUntil([&] { return session.capabilities().probed && session.hasPosition(); }, 10000);
    sim::Simulator *sim = sim::simulatorBehind(session.link());
    const tracking::RotatorReach reach = tracking::reachOf(session);
    const double t0 = sim->clock().now();
    double skipped = 0;
    const double j0 = taken.first().startJulian - kLongestWaitS / sky::kSecondsPerDay;
    auto julianNow = [&] { return j0 + (sim->clock().now() - t0 + skipped) / sky::kSecondsPerDay; };

    tracking::Tracker tracker(&session);
    tracking::TrackerSettings settings;
    settings.afterPass = tracking::TrackerSettings::AfterPass::Stay;
    tracker.setSettings(tracking::trackerSettingsFor(session.profile().motion, settings));
    QList<tracking::TrackingFigures> figures;
    for (const ScheduledPass &p : taken) {
        const double gap = (p.startJulian - julianNow()) * sky::kSecondsPerDay;
        if (gap > kLongestWaitS)
            skipped += gap - kLongestWaitS;
        if (!tracker.track(p.points, p.plan, p.startJulian, reach, julianNow)) {
            std::printf("cannot track %s: %s\n", qPrintable(p.target), qPrintable(tracker.error()));
            figures.append(tracking::TrackingFigures{});
            continue;
        }
        runEventLoopUntil([&] { return tracker.state() == tracking::Tracker::State::Done
                                       || tracker.state() == tracking::Tracker::State::Idle; },
                          600000);
        figures.append(tracker.figures());
    }
    *simulatedSeconds = sim->clock().now() - t0;
    return figures;
}

// Slew's schedule and the autotrack style on the same day for one rotator:
// the plan's decisions, and the passes of each priority each loses.
schedule::Schedule compare(const QList<tracking::TrackTarget> &list, const schedule::ScheduleSettings &settings,
                           const tracking::RotatorReach &reach, const char *rotator)
{
    QElapsedTimer planning;
    planning.start();
    const schedule::Schedule plan = schedule::planSchedule(list, jo65hq(), reach, settings);
    const qint64 planMs = planning.elapsed();
    std::printf("\n== %s (%.0f°/%.0f°)\nSlew's schedule (planned in %lld ms): %s\n", rotator, reach.limits.azMax,
                reach.limits.elMax, planMs, qPrintable(schedule::describeScheduleSummary(plan)));
    std::map<QString, int> reasons;
    for (const ScheduledPass &p : plan.passes)
        if (!p.taken)
            ++reasons[schedule::reasonWord(p.reason)];
    for (const auto &[word, count] : reasons)
        std::printf("  dropped, %s: %d\n", qPrintable(word), count);

    const QList<ScheduledPass> all = everyPass(plan);
    const Autotrack gpredict = autotrack(all, reach);
    std::printf("%-22s %6s %14s %16s\n", "priority", "passes", "Slew loses", "autotrack loses");
    int slewTop = 0, autoTop = 0;
    for (int priority = 0; priority < kTargetCount; ++priority) {
        int day = 0, slewTook = 0, autoTook = 0;
        for (const ScheduledPass &p : all)
            if (p.priority == priority && p.reason != schedule::DropReason::BelowHorizon)
                ++day;
        for (const ScheduledPass &p : plan.passes)
            slewTook += p.taken && p.priority == priority ? 1 : 0;
        for (const ScheduledPass &p : gpredict.taken)
            autoTook += p.priority == priority ? 1 : 0;
        if (priority < 3) {
            slewTop += day - slewTook;
            autoTop += day - autoTook;
        }
        std::printf("%d. %-19s %6d %14d %16d\n", priority + 1, kTargets[priority], day, day - slewTook, day - autoTook);
    }
    std::printf("the three highest priorities: Slew loses %d passes, the autotrack style %d\n", slewTop, autoTop);
    std::printf("autotrack takes %d passes, %d of them starting out of the rotator's reach from the last LOS "
                "(Slew: none, by construction)\n",
                int(gpredict.taken.size()), gpredict.outOfReach);
    return plan;
}

tracking::RotatorReach g5500(double azMax, double elMax)
{
    return tracking::reachOf(model::RotatorLimits{0, azMax, 0, elMax}, model::RotatorProfile{}.motion);
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    registerLinkSchemes();
    const QList<tracking::TrackTarget> list = targets();
    if (list.size() != kTargetCount)
        return 1;
    schedule::ScheduleSettings settings;
    settings.startJulian = *sky::julianFromIso(QStringLiteral("2018-01-22T00:00:00Z"));
    settings.hours = 24;
    settings.minElevationDeg = 5; // lower passes are of little use to anyone
    settings.guardSeconds = 30;
    settings.antennaAt = schedule::AntennaPoint{0, 0}; // parked

    const tracking::RotatorReach reach = g5500(450, 180);
    std::printf("24 h from 2018-01-22 00:00 UTC over JO65hq, passes above 5°, a 30 s guard; a G-5500 class rotator "
                "(%.1f°/s azimuth, %.1f°/s elevation), parked at the start\n",
                reach.azimuthRateDegS, reach.elevationRateDegS);
    for (int i = 0; i < kTargetCount; ++i)
        std::printf("  priority %d: %s\n", i + 1, kTargets[i]);
    compare(list, settings, g5500(360, 90), "a 360° rotator without the flip");
    const schedule::Schedule plan = compare(list, settings, reach, "the G-5500 with its overlap and flip");
    QList<ScheduledPass> taken;
    for (const ScheduledPass &p : plan.passes)
        if (p.taken)
            taken.append(p);

    std::printf("\nEvery pass of the day on the G-5500:\n");
    for (const ScheduledPass &p : plan.passes)
        std::printf("  %s\n", qPrintable(schedule::describeScheduledPass(p)));

    QElapsedTimer wall;
    wall.start();
    double simulated = 0;
    const QList<tracking::TrackingFigures> figures = follow(taken, &simulated);
    std::printf("\nThe taken passes followed on the simulated rotator, in turn (pointing error from AOS + 5 s to "
                "LOS):\n");
    std::printf("  %-19s %-24s %7s %9s %9s %10s %8s\n", "UTC", "target", "max el", "RMS", "worst", "plan worst",
                "commands");
    double worstRms = 0, worstWorst = 0;
    for (int i = 0; i < taken.size(); ++i) {
        const ScheduledPass &p = taken[i];
        const tracking::TrackingFigures &f = figures.value(i);
        worstRms = std::max(worstRms, f.rmsDeg);
        worstWorst = std::max(worstWorst, f.worstDeg);
        std::printf("  %-19s %-24s %6.1f° %8.3f° %8.2f° %9.2f° %8d\n",
                    qPrintable(sky::utcFromJulian(p.startJulian).toString(QStringLiteral("yyyy-MM-dd HH:mm:ss"))),
                    qPrintable(p.target), p.pass.maxElevationDeg(), f.rmsDeg, f.worstDeg, p.predictedWorstDeg,
                    f.commands);
    }
    std::printf("  the largest RMS of any pass: %.3f°, the largest worst: %.2f°; %d passes, %.0f simulated s in "
                "%.1f s\n",
                worstRms, worstWorst, int(taken.size()), simulated, wall.elapsed() / 1000.0);
    return 0;
}
