// SPDX-License-Identifier: GPL-3.0-or-later
#include "schedulerunner.h"

#include "face/schedulerequest.h"
#include "input/finitenumber.h"
#include "schedule/scheduletext.h"
#include "session/rotatorsession.h"
#include "sky/utctime.h"
#include "tracking/rotatorreach.h"
#include "tracking/stationclock.h"

#include <QFutureWatcher>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>
#include <limits>

namespace slew::station {

using schedule::ScheduledPass;
using tracking::PassRunner;

namespace {

// Two passes closer than this: the antenna waits where the first left it.
constexpr double kStayBetweenSeconds = 600.0;
// A plan that took nothing is made again after this long at the latest.
constexpr double kEmptyPlanAgainDays = 1.0 / 24.0;

} // namespace

QString scheduleOptionsFault(const ScheduleOptions &options)
{
    QString why;
    if (!input::checkNumber(options.hours, face::kScheduleHours, &why))
        return ScheduleRunner::tr("a schedule's hours: %1").arg(why);
    if (!input::checkNumber(options.minElevationDeg, face::kScheduleMinElevation, &why))
        return ScheduleRunner::tr("a schedule's minimum elevation: %1").arg(why);
    if (!input::checkNumber(options.guardSeconds, face::kScheduleGuard, &why))
        return ScheduleRunner::tr("a schedule's guard time: %1").arg(why);
    return {};
}

schedule::ScheduleSettings scheduleSettingsNow(const session::RotatorSession &session, const PassRunner &runner,
                                               const tracking::StationClock &clock, const ScheduleOptions &options)
{
    schedule::ScheduleSettings settings;
    settings.startJulian = clock.nowJulian();
    settings.hours = options.hours;
    settings.minElevationDeg = options.minElevationDeg;
    settings.guardSeconds = options.guardSeconds;
    settings.maxElementAgeDays = runner.elementAgeLimitDays();
    if (session.hasPosition())
        settings.antennaAt = schedule::AntennaPoint{session.azimuth(), session.elevation()};
    return settings;
}

ScheduleRunner::ScheduleRunner(session::RotatorSession *session, PassRunner *runner,
                               const tracking::StationClock *clock, QObject *parent)
    : QObject(parent), m_session(session), m_runner(runner), m_clock(clock)
{
    m_wake.setSingleShot(true);
    connect(&m_wake, &QTimer::timeout, this, [this] {
        if (!m_running || m_planning)
            return;
        const double now = m_clock->nowJulian();
        sayDroppedUpTo(now);
        const double halfway = m_schedule.settings.startJulian + m_schedule.settings.hours / 48.0;
        if (now >= halfway && !m_current)
            plan(tr("half of the planned hours have gone by"));
        else
            advance();
    });
    connect(m_runner, &PassRunner::onePassEnded, this, &ScheduleRunner::onOneEnded);
}

ScheduleRunner::~ScheduleRunner()
{
    cancelPlanning();
}

void ScheduleRunner::cancelPlanning()
{
    if (m_planStop)
        m_planStop->store(true);
    m_planStop.reset();
    ++m_generation;
    m_planning = false;
    m_planAgain = false;
}

QString ScheduleRunner::keyOf(const ScheduledPass &pass) const
{
    return QStringLiteral("%1@%2").arg(pass.target).arg(qint64(std::llround(pass.startJulian * sky::kSecondsPerDay)));
}

void ScheduleRunner::start(const QList<tracking::TrackTarget> &targets, const sky::Site &place,
                           const ScheduleOptions &options)
{
    if (m_running)
        stop(tr("a new schedule"));
    m_targets = targets;
    m_place = place;
    m_options = options;
    m_running = true;
    m_current.reset();
    m_doneUntil = 0;
    m_saidDropped.clear();
    m_schedule = schedule::Schedule{};
    disconnect(m_clockChanged);
    // A pass under way ends by itself on a new clock (onOneEnded); between
    // passes the plan is made again here.
    m_clockChanged = connect(m_clock, &tracking::StationClock::changed, this, [this] {
        if (!m_current) {
            m_doneUntil = 0;
            plan(tr("the station clock was changed"));
        }
    });
    QStringList names;
    for (int i = 0; i < targets.size(); ++i)
        names << QStringLiteral("%1. %2").arg(i + 1).arg(targets[i].name());
    emit logLine(tr("schedule: targets by priority: %1").arg(names.join(QStringLiteral(", "))));
    emit runningChanged(true);
    plan(tr("started"));
}

void ScheduleRunner::stop(const QString &why)
{
    if (!m_running)
        return;
    m_running = false;
    cancelPlanning();
    m_wake.stop();
    disconnect(m_clockChanged);
    if (m_current) {
        m_current.reset();
        m_runner->stop(why); // its end is not ours to follow any more
        emit currentChanged();
    }
    emit logLine(tr("schedule: ended: %1").arg(why));
    emit runningChanged(false);
}

void ScheduleRunner::setTargets(const QList<tracking::TrackTarget> &targets)
{
    m_targets = targets;
    if (!m_running)
        return;
    if (m_current && m_runner->holdsRotator()) {
        const bool stillListed = std::any_of(targets.begin(), targets.end(), [&](const tracking::TrackTarget &t) {
            return t.name() == m_current->target;
        });
        if (!stillListed)
            emit logLine(tr("schedule: the pass of %1 in progress is followed to its end at %2, though %1 is no "
                            "longer in the list")
                             .arg(m_current->target, sky::isoUtc(m_current->endJulian)));
    }
    plan(tr("the targets changed"));
}

std::optional<tracking::TrackTarget> ScheduleRunner::targetNamed(const QString &name) const
{
    for (const tracking::TrackTarget &t : m_targets)
        if (t.name() == name)
            return t;
    return std::nullopt;
}

void ScheduleRunner::updateElements(const QList<sky::ElementSet> &sets)
{
    bool changed = false;
    for (tracking::TrackTarget &t : m_targets) {
        if (t.kind != tracking::TrackTarget::Kind::Satellite)
            continue;
        for (const sky::ElementSet &set : sets) {
            if (set.catalogueNumber == t.elements.catalogueNumber && set.epochJulian() > t.elements.epochJulian()) {
                t.elements = set;
                changed = true;
            }
        }
    }
    if (changed && m_running)
        plan(tr("the element sets were refreshed"));
}

void ScheduleRunner::plan(const QString &why)
{
    if (!m_running)
        return;
    if (m_planning) {
        m_planAgain = true;
        m_planAgainWhy = why;
        return;
    }
    m_wake.stop();
    const schedule::ScheduleSettings settings = scheduleSettingsNow(*m_session, *m_runner, *m_clock, m_options);
    // The pass the rotator is on (or moving to) is not taken away from it.
    QList<ScheduledPass> pinned;
    if (m_current && m_runner->holdsRotator())
        pinned.append(*m_current);
    const tracking::RotatorReach reach = tracking::reachOf(*m_session);
    m_planning = true;
    const int generation = ++m_generation;
    m_planStop = std::make_shared<std::atomic<bool>>(false);
    auto *watcher = new QFutureWatcher<schedule::Schedule>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, generation, why] {
        watcher->deleteLater();
        if (generation != m_generation)
            return; // stopped, or planned again meanwhile
        m_planning = false;
        onPlanned(watcher->result(), why);
    });
    watcher->setFuture(QtConcurrent::run([targets = m_targets, place = m_place, reach, settings, pinned,
                                          stop = m_planStop] {
        return schedule::planSchedule(targets, place, reach, settings, pinned, stop.get());
    }));
}

void ScheduleRunner::onPlanned(const schedule::Schedule &made, const QString &why)
{
    if (m_planAgain) {
        m_planAgain = false;
        plan(m_planAgainWhy);
        return;
    }
    m_schedule = made;
    emit logLine(tr("schedule: planned (%1): %2").arg(why, schedule::describeScheduleSummary(made)));
    for (const ScheduledPass &p : made.passes)
        emit logLine(tr("schedule: %1").arg(schedule::describeScheduledPass(p)));
    for (const QString &note : made.notes)
        emit logLine(tr("schedule: %1").arg(note));
    emit scheduleChanged();
    // A pass waited for (not yet on the rotator) that the new plan does not
    // take any more is let go.
    if (m_current && !m_runner->holdsRotator()) {
        const QString key = keyOf(*m_current);
        const bool kept = std::any_of(made.passes.begin(), made.passes.end(),
                                      [&](const ScheduledPass &p) { return p.taken && keyOf(p) == key; });
        if (!kept) {
            emit logLine(tr("schedule: %1's pass of %2 is not in the new plan: let go")
                             .arg(m_current->target, sky::isoUtc(m_current->startJulian)));
            m_current.reset();
            m_runner->stop(tr("the schedule was planned again")); // its end is not followed (m_current is empty)
            emit currentChanged();
        }
    }
    advance();
}

std::optional<ScheduledPass> ScheduleRunner::nextTaken(double nowJulian) const
{
    for (const ScheduledPass &p : m_schedule.passes) {
        if (p.taken && p.endJulian > nowJulian && p.startJulian >= m_doneUntil - 1e-9)
            return p;
    }
    return std::nullopt;
}

void ScheduleRunner::advance()
{
    if (!m_running || m_planning)
        return;
    const double now = m_clock->nowJulian();
    sayDroppedUpTo(now);
    if (m_current) {
        armTimer();
        return; // the runner is on it; onOneEnded() comes next
    }
    const std::optional<ScheduledPass> next = nextTaken(now);
    if (!next) {
        armTimer();
        return;
    }
    if (next->priority < 0 || next->priority >= m_targets.size()) {
        plan(tr("the targets changed"));
        return;
    }
    m_current = *next;
    emit currentChanged();
    // The pass after: close, and the antenna waits where this one leaves it.
    std::optional<ScheduledPass> after;
    for (const ScheduledPass &p : m_schedule.passes)
        if (p.taken && p.startJulian >= next->endJulian) {
            after = p;
            break;
        }
    const bool stay = after && (after->startJulian - next->endJulian) * sky::kSecondsPerDay < kStayBetweenSeconds;
    m_runner->setAfterPass(stay ? tracking::TrackerSettings::AfterPass::Stay
                                : tracking::TrackerSettings::AfterPass::Park);
    emit logLine(tr("schedule: next: %1").arg(schedule::describeScheduledPass(*next)));
    m_runner->startOne(m_targets[next->priority], m_place, m_options.minElevationDeg, m_clock, next->startJulian,
                       next->endJulian);
    armTimer();
}

void ScheduleRunner::onOneEnded(PassRunner::OneEnd end, const QString &why)
{
    if (!m_running || !m_current)
        return; // not a pass of ours (let go, or the schedule has ended)
    const ScheduledPass done = *m_current;
    m_current.reset();
    emit currentChanged();
    switch (end) {
    case PassRunner::OneEnd::Tracked:
        m_doneUntil = done.endJulian;
        advance();
        break;
    case PassRunner::OneEnd::NotFound:
        emit logLine(tr("schedule: %1: %2").arg(done.target, why));
        m_doneUntil = done.endJulian;
        advance();
        break;
    case PassRunner::OneEnd::Stopped:
        stop(tr("tracking was stopped: %1").arg(why));
        break;
    case PassRunner::OneEnd::ClockChanged:
        m_doneUntil = 0;
        plan(tr("the station clock was changed"));
        break;
    }
}

void ScheduleRunner::sayDroppedUpTo(double julian)
{
    for (const ScheduledPass &p : m_schedule.passes) {
        if (p.taken || p.startJulian > julian)
            continue;
        const QString key = keyOf(p);
        if (m_saidDropped.contains(key))
            continue;
        m_saidDropped.insert(key);
        emit logLine(tr("schedule: dropped: %1").arg(schedule::describeScheduledPass(p)));
        emit passDropped(p);
    }
}

void ScheduleRunner::armTimer()
{
    if (!m_running)
        return;
    const double now = m_clock->nowJulian();
    // Plan again halfway through the window, or within the hour when it
    // took nothing (during a pass: once it has ended); and wake for the
    // next dropped pass to be said.
    double wakeAt = std::numeric_limits<double>::infinity();
    double planAgainAt = m_schedule.settings.startJulian + m_schedule.settings.hours / 48.0;
    if (m_schedule.takenCount() == 0)
        planAgainAt = std::min(planAgainAt, m_schedule.settings.startJulian + kEmptyPlanAgainDays);
    if (!m_current || planAgainAt > now)
        wakeAt = planAgainAt;
    for (const ScheduledPass &p : m_schedule.passes) {
        if (!p.taken && p.startJulian > now && !m_saidDropped.contains(keyOf(p))) {
            wakeAt = std::min(wakeAt, p.startJulian);
            break; // by start: the first is the nearest
        }
    }
    if (!std::isfinite(wakeAt)) {
        m_wake.stop();
        return;
    }
    const double rate = std::max(1.0, m_clock->rate());
    const double ms = std::clamp((wakeAt - now) * sky::kSecondsPerDay * 1000.0 / rate, 0.0,
                                 double(std::numeric_limits<int>::max() / 2));
    m_wake.start(int(ms));
}

} // namespace slew::station
