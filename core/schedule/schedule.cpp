// SPDX-License-Identifier: GPL-3.0-or-later
#include "schedule.h"

#include "tracking/rotatorreach.h"

#include "input/finitenumber.h"
#include "sky/elementage.h"
#include "sky/utctime.h"

#include <QObject>

#include <algorithm>
#include <cmath>

namespace slew::schedule {

using tracking::PassPlan;
using tracking::PlannerOptions;
using tracking::SkyPoint;

namespace {

constexpr double kSecond = 1.0 / sky::kSecondsPerDay;
// The longest window a schedule is planned for: a week.
constexpr double kMostHours = 168.0;

QString clockTime(double julian)
{
    return sky::utcFromJulian(julian).toString(QStringLiteral("HH:mm:ss"));
}

// "FLOCK 2P-1 (priority 1, 09:17:51–09:25:04 UTC)"
QString named(const ScheduledPass &p)
{
    return QObject::tr("%1 (priority %2, %3–%4 UTC)")
        .arg(p.target)
        .arg(p.priority + 1)
        .arg(clockTime(p.startJulian), clockTime(p.endJulian));
}

QString position(const AntennaPoint &p)
{
    return QObject::tr("az %1°, el %2°").arg(p.azimuth, 0, 'f', 1).arg(p.elevation, 0, 'f', 1);
}

void setPlan(ScheduledPass &p, const PassPlan &plan)
{
    p.plan = plan;
    if (!plan.isValid())
        return;
    p.first = {plan.path.front().azimuth, plan.path.front().elevation};
    p.last = {plan.path.back().azimuth, plan.path.back().elevation};
    p.predictedWorstDeg = plan.predictedWorstDeg;
}

// The pass planned again from where the antenna will be, when that plan is
// as good: a 450° rotator then starts in the overlap instead of turning back.
ScheduledPass plannedFrom(const ScheduledPass &p, const AntennaPoint &from, const tracking::RotatorReach &reach)
{
    ScheduledPass again = p;
    PlannerOptions options;
    options.startAzimuth = from.azimuth;
    const PassPlan plan = tracking::planPass(p.points, reach, options);
    if (plan.isValid() && plan.predictedWorstDeg <= p.predictedWorstDeg + 1e-9)
        setPlan(again, plan);
    return again;
}

bool isLong(const ScheduledPass &p)
{
    return p.norad == 0; // the sun, the moon, a radio source, a fixed direction
}

// The bearing halfway along from a to b, the short way round.
double azimuthBetween(double a, double b, double f)
{
    double az = a + f * std::remainder(b - a, 360.0);
    if (az < 0)
        az += 360.0;
    return std::fmod(az, 360.0);
}

// The sky from `from` to `to` (seconds of the pass's points), the ends
// interpolated, seconds counted from `from` again.
QList<SkyPoint> slice(const QList<SkyPoint> &points, double from, double to)
{
    QList<SkyPoint> out;
    auto at = [&](double s) {
        const auto after = std::lower_bound(points.begin(), points.end(), s,
                                            [](const SkyPoint &p, double t) { return p.seconds < t; });
        if (after == points.begin())
            return points.front();
        if (after == points.end())
            return points.back();
        const SkyPoint &a = *std::prev(after), &b = *after;
        const double f = b.seconds > a.seconds ? (s - a.seconds) / (b.seconds - a.seconds) : 0.0;
        return SkyPoint{s, azimuthBetween(a.azimuthDeg, b.azimuthDeg, f),
                        a.elevationDeg + f * (b.elevationDeg - a.elevationDeg)};
    };
    if (points.isEmpty() || !(to > from))
        return out;
    out.append(at(from));
    for (const SkyPoint &p : points)
        if (p.seconds > from && p.seconds < to)
            out.append(p);
    out.append(at(to));
    for (SkyPoint &p : out)
        p.seconds -= from;
    return out;
}

class Arranger {
public:
    Arranger(const tracking::RotatorReach &reach, const ScheduleSettings &settings) : m_reach(reach), m_settings(settings)
    {
    }

    void pin(ScheduledPass p)
    {
        p.taken = true;
        p.pinned = true;
        p.reason = DropReason::None;
        m_timeline.insert(indexAfter(p.startJulian), p);
    }

    void offer(ScheduledPass c)
    {
        if (c.reason != DropReason::None) {
            m_dropped.append(c); // dropped before it came here (horizon, elements, plan)
            return;
        }
        if (isLong(c))
            fitPieces(c);
        else
            take(c);
    }

    QList<ScheduledPass> all() const
    {
        QList<ScheduledPass> out = m_timeline + m_dropped;
        std::stable_sort(out.begin(), out.end(), [](const ScheduledPass &a, const ScheduledPass &b) {
            return a.startJulian != b.startJulian ? a.startJulian < b.startJulian : a.priority < b.priority;
        });
        return out;
    }

private:
    double guard() const { return m_settings.guardSeconds * kSecond; }

    // Where a pass starting at `julian` goes in the timeline.
    qsizetype indexAfter(double julian) const
    {
        qsizetype i = 0;
        while (i < m_timeline.size() && m_timeline[i].startJulian < julian)
            ++i;
        return i;
    }

    const ScheduledPass *overlapping(double start, double end) const
    {
        for (const ScheduledPass &t : m_timeline)
            if (start < t.endJulian + guard() && t.startJulian < end + guard())
                return &t;
        return nullptr;
    }

    void drop(ScheduledPass c, DropReason reason, const QString &why)
    {
        c.taken = false;
        c.reason = reason;
        c.why = why;
        m_dropped.append(c);
    }

    // Seconds from the end of the pass before (or the schedule's start) to `start`, the guard taken off.
    double timeBefore(qsizetype index, double start) const
    {
        if (index > 0)
            return (start - m_timeline[index - 1].endJulian) * sky::kSecondsPerDay - m_settings.guardSeconds;
        return (start - m_settings.startJulian) * sky::kSecondsPerDay;
    }
    std::optional<AntennaPoint> antennaBefore(qsizetype index) const
    {
        if (index > 0)
            return m_timeline[index - 1].last;
        return m_settings.antennaAt;
    }

    // Why `c`, going in at `index`, cannot be reached from the pass before
    // or leaves the pass after out of reach; empty when it fits. May plan
    // `c` and the pass after again from where the antenna will be.
    QString reachProblem(ScheduledPass &c, qsizetype index, std::optional<ScheduledPass> *nextReplanned)
    {
        // A pass under way when the schedule starts, with none before it, is
        // joined late: there was never time to be at its first point.
        const bool underWay = index == 0 && c.startJulian <= m_settings.startJulian + kSecond;
        if (const std::optional<AntennaPoint> from = antennaBefore(index)) {
            c = plannedFrom(c, *from, m_reach);
            const double need = moveSeconds(m_reach, *from, c.first);
            const double have = timeBefore(index, c.startJulian);
            if (need > have && !underWay) {
                const QString where = index > 0 ? QObject::tr("where %1 leaves it (%2)")
                                                      .arg(named(m_timeline[index - 1]), position(*from))
                                                : QObject::tr("where the antenna stands at the start (%1)").arg(position(*from));
                return QObject::tr("the rotator cannot reach its AOS point (%1) from %2 in time: the move takes %3 s, "
                                   "and there are %4 s")
                    .arg(position(c.first), where)
                    .arg(need, 0, 'f', 0)
                    .arg(std::max(0.0, have), 0, 'f', 0);
            }
        }
        if (index < m_timeline.size()) {
            const ScheduledPass &next = m_timeline[index];
            const double have = (next.startJulian - c.endJulian) * sky::kSecondsPerDay - m_settings.guardSeconds;
            if (moveSeconds(m_reach, c.last, next.first) <= have)
                return {};
            // The pass after, planned from here, may start nearer (the overlap).
            if (!next.pinned) {
                const ScheduledPass again = plannedFrom(next, c.last, m_reach);
                const bool afterStillFits =
                    index + 1 >= m_timeline.size()
                    || moveSeconds(m_reach, again.last, m_timeline[index + 1].first)
                           <= (m_timeline[index + 1].startJulian - again.endJulian) * sky::kSecondsPerDay
                                  - m_settings.guardSeconds;
                if (moveSeconds(m_reach, c.last, again.first) <= have && afterStillFits) {
                    *nextReplanned = again;
                    return {};
                }
            }
            return QObject::tr("taking it would leave the rotator %1 s to reach the AOS point of %2 (%3), and the "
                               "move takes %4 s")
                .arg(std::max(0.0, have), 0, 'f', 0)
                .arg(named(next), position(next.first))
                .arg(moveSeconds(m_reach, c.last, next.first), 0, 'f', 0);
        }
        return {};
    }

    void take(ScheduledPass c)
    {
        if (const ScheduledPass *other = overlapping(c.startJulian, c.endJulian)) {
            drop(c, DropReason::Overlap, QObject::tr("overlaps %1").arg(named(*other)));
            return;
        }
        const qsizetype index = indexAfter(c.startJulian);
        std::optional<ScheduledPass> next;
        if (const QString problem = reachProblem(c, index, &next); !problem.isEmpty()) {
            drop(c, DropReason::Unreachable, problem);
            return;
        }
        if (next)
            m_timeline[index] = *next;
        c.taken = true;
        m_timeline.insert(index, c);
    }

    // A long target: what of its time overlaps nothing, piece by piece.
    void fitPieces(const ScheduledPass &c)
    {
        const double shortest = m_settings.shortestPieceSeconds * kSecond;
        QList<std::pair<double, double>> gaps{{c.startJulian, c.endJulian}};
        for (const ScheduledPass &t : m_timeline) {
            QList<std::pair<double, double>> rest;
            for (const auto &[a, b] : gaps) {
                const double busyFrom = t.startJulian - guard(), busyTo = t.endJulian + guard();
                if (busyTo <= a || busyFrom >= b) {
                    rest.append({a, b});
                    continue;
                }
                if (busyFrom > a)
                    rest.append({a, busyFrom});
                if (busyTo < b)
                    rest.append({busyTo, b});
            }
            gaps = rest;
        }
        int pieces = 0;
        for (const auto &[a, b] : gaps) {
            if (b - a < shortest)
                continue;
            const double offset = (a - c.startJulian) * sky::kSecondsPerDay;
            ScheduledPass piece = c;
            piece.startJulian = a;
            piece.endJulian = b;
            piece.points = slice(c.points, offset, (b - c.startJulian) * sky::kSecondsPerDay);
            setPlan(piece, tracking::planPass(piece.points, m_reach));
            if (!piece.plan.isValid())
                continue;
            // Room to get there, and to leave for the pass after.
            const qsizetype index = indexAfter(a);
            if (const std::optional<AntennaPoint> from = antennaBefore(index)) {
                piece = plannedFrom(piece, *from, m_reach);
                const double late = moveSeconds(m_reach, *from, piece.first) - timeBefore(index, a);
                if (late > 0)
                    piece.startJulian += late * kSecond;
            }
            if (index < m_timeline.size()) {
                const ScheduledPass &next = m_timeline[index];
                const double early = moveSeconds(m_reach, piece.last, next.first)
                                     - ((next.startJulian - piece.endJulian) * sky::kSecondsPerDay
                                        - m_settings.guardSeconds);
                if (early > 0)
                    piece.endJulian -= early * kSecond;
            }
            if (piece.endJulian - piece.startJulian < shortest)
                continue;
            if (piece.startJulian != a || piece.endJulian != b) {
                piece.points = slice(c.points, (piece.startJulian - c.startJulian) * sky::kSecondsPerDay,
                                     (piece.endJulian - c.startJulian) * sky::kSecondsPerDay);
                setPlan(piece, tracking::planPass(piece.points, m_reach));
            }
            if (piece.startJulian > c.startJulian + 1e-9 || piece.endJulian < c.endJulian - 1e-9)
                piece.why = QObject::tr("from %1 to %2 UTC, between other passes")
                                .arg(clockTime(piece.startJulian), clockTime(piece.endJulian));
            piece.taken = true;
            m_timeline.insert(indexAfter(piece.startJulian), piece);
            ++pieces;
        }
        if (pieces == 0) {
            const ScheduledPass *other = overlapping(c.startJulian, c.endJulian);
            drop(c, other ? DropReason::Overlap : DropReason::NoRoomLeft,
                 other ? QObject::tr("no gap of %1 min left between the passes taken (first: %2)")
                             .arg(m_settings.shortestPieceSeconds / 60.0, 0, 'f', 0)
                             .arg(named(*other))
                       : QObject::tr("shorter than %1 min").arg(m_settings.shortestPieceSeconds / 60.0, 0, 'f', 0));
        }
    }

    const tracking::RotatorReach &m_reach;
    const ScheduleSettings &m_settings;
    QList<ScheduledPass> m_timeline; // taken, by start
    QList<ScheduledPass> m_dropped;
};

bool settingsUsable(const ScheduleSettings &s)
{
    return input::allFinite(s.startJulian, s.hours, s.minElevationDeg, s.guardSeconds, s.maxElementAgeDays,
                            s.shortestPieceSeconds)
           && s.hours > 0 && s.hours <= kMostHours && s.guardSeconds >= 0 && s.maxElementAgeDays > 0
           && s.shortestPieceSeconds > 0;
}

} // namespace

int Schedule::takenCount() const
{
    return int(std::count_if(passes.begin(), passes.end(), [](const ScheduledPass &p) { return p.taken; }));
}

int Schedule::droppedCount() const
{
    return int(passes.size()) - takenCount();
}

std::optional<ScheduledPass> Schedule::takenAtOrAfter(double julian) const
{
    for (const ScheduledPass &p : passes)
        if (p.taken && p.endJulian > julian)
            return p;
    return std::nullopt;
}

double moveSeconds(const tracking::RotatorReach &reach, const AntennaPoint &from, const AntennaPoint &to)
{
    const double az = tracking::stepSeconds(std::abs(to.azimuth - from.azimuth), reach.azimuthRateDegS,
                                            reach.azimuthAccelDegS2);
    const double el = tracking::stepSeconds(std::abs(to.elevation - from.elevation), reach.elevationRateDegS,
                                            reach.elevationAccelDegS2);
    return std::max(az, el);
}

Schedule arrangeSchedule(const QList<QList<ScheduledPass>> &candidatesByPriority, const tracking::RotatorReach &reach,
                         const ScheduleSettings &settings, const QList<ScheduledPass> &pinned)
{
    Schedule out;
    out.settings = settings;
    Arranger arranger(reach, settings);
    for (const ScheduledPass &p : pinned)
        arranger.pin(p);
    for (const QList<ScheduledPass> &candidates : candidatesByPriority)
        for (const ScheduledPass &c : candidates)
            arranger.offer(c);
    out.passes = arranger.all();
    return out;
}

Schedule planSchedule(const QList<tracking::TrackTarget> &targets, const sky::Site &station,
                      const tracking::RotatorReach &reach, const ScheduleSettings &settings,
                      const QList<ScheduledPass> &pinned, const std::atomic<bool> *stop)
{
    Schedule out;
    out.settings = settings;
    for (const tracking::TrackTarget &t : targets)
        out.targets << t.name();
    if (!settingsUsable(settings)) {
        out.notes << QObject::tr("nothing planned: the window or a setting is not a usable number");
        return out;
    }
    // AOS and LOS at the horizon (or the mask), as everywhere; the minimum
    // elevation keeps the passes that climb to it.
    const sky::PassWindow window{settings.startJulian, settings.startJulian + settings.hours / 24.0, 0.0, stop,
                                 settings.minElevationDeg};
    sky::Site flat = station;
    flat.horizon.reset();
    QList<QList<ScheduledPass>> byPriority;
    for (int priority = 0; priority < targets.size(); ++priority) {
        if (stop && stop->load())
            break;
        const tracking::TrackTarget &target = targets[priority];
        const tracking::TargetSky sky(target);
        const bool satellite = target.kind == tracking::TrackTarget::Kind::Satellite;
        QList<ScheduledPass> candidates;
        auto candidate = [&](const sky::Pass &p) {
            ScheduledPass c;
            c.priority = priority;
            c.target = target.name();
            c.norad = satellite ? target.elements.catalogueNumber : 0;
            c.pass = p;
            c.startJulian = std::max(p.aos.julian, window.startJulian);
            c.endJulian = target.isFixed() ? window.endJulian : p.los.julian;
            return c;
        };
        const QList<sky::Pass> passes = sky.passes(station, window);
        if (station.horizon) {
            for (const sky::Pass &open : sky.passes(flat, window)) {
                const bool shows = std::any_of(passes.begin(), passes.end(), [&](const sky::Pass &p) {
                    return p.aos.julian < open.los.julian && open.aos.julian < p.los.julian;
                });
                if (shows)
                    continue;
                ScheduledPass hidden = candidate(open);
                hidden.reason = DropReason::BelowHorizon;
                hidden.why = QObject::tr("never clears the horizon mask: highest %1° at azimuth %2°, where the mask "
                                         "is %3°")
                                 .arg(open.maxElevationDeg(), 0, 'f', 1)
                                 .arg(open.tca.azimuthDeg, 0, 'f', 1)
                                 .arg(station.horizon->elevationAt(open.tca.azimuthDeg), 0, 'f', 1);
                candidates.append(hidden);
            }
        }
        for (const sky::Pass &p : passes) {
            ScheduledPass c = candidate(p);
            if (const QString old = satellite ? sky::elementsTooOld(target.elements, p.aos.julian,
                                                                      settings.maxElementAgeDays, QObject::tr("AOS"))
                                              : QString();
                !old.isEmpty()) {
                c.reason = DropReason::StaleElements;
                c.why = old;
            } else {
                c.points = sky.sample(station, p, c.startJulian);
                if (target.isFixed()) {
                    // One stretch the length of the window: its points say so.
                    sky::Pass held = p;
                    held.los.julian = c.endJulian;
                    c.points = sky.sample(station, held, c.startJulian);
                }
                setPlan(c, tracking::planPass(c.points, reach));
                if (!c.plan.isValid()) {
                    c.reason = DropReason::NoPlan;
                    c.why = QObject::tr("no path the rotator can drive: %1").arg(c.plan.refusal);
                }
            }
            candidates.append(c);
        }
        std::stable_sort(candidates.begin(), candidates.end(),
                         [](const ScheduledPass &a, const ScheduledPass &b) { return a.startJulian < b.startJulian; });
        if (candidates.isEmpty())
            out.notes << QObject::tr("%1: no pass above %2° in these %3 hours")
                             .arg(target.name())
                             .arg(settings.minElevationDeg)
                             .arg(settings.hours);
        byPriority.append(candidates);
    }
    Schedule arranged = arrangeSchedule(byPriority, reach, settings, pinned);
    out.passes = arranged.passes;
    return out;
}

} // namespace slew::schedule
