// SPDX-License-Identifier: GPL-3.0-or-later
#include "planpublisher.h"

#include "schedulerunner.h"
#include "station.h"

#include "remote/stationplan.h"
#include "remote/stationschedule.h"
#include "remote/stationtopics.h"
#include "session/rotatorsession.h"
#include "tracking/passrunner.h"
#include "tracking/stationclock.h"

#include <QDateTime>

#include <cmath>

namespace slew::station {
namespace {

qint64 unixMs(double julian)
{
    return qint64(std::llround((julian - 2440587.5) * 86400000.0));
}

remote::StationPlan planNow(const Station &station, qint64 now)
{
    remote::StationPlan out;
    out.unixMs = now;
    const tracking::PassRunner *runner = station.passRunner();
    if (!runner || !runner->isRunning() || !runner->pass())
        return out;
    const tracking::Tracker &tracker = runner->tracker();
    if (tracker.state() != tracking::Tracker::State::Waiting && tracker.state() != tracking::Tracker::State::Tracking)
        return out;
    const sky::Pass &pass = *runner->pass();
    out.target = runner->target().name().left(100);
    out.norad = pass.catalogueNumber;
    out.aosMs = unixMs(pass.aos.julian);
    out.tcaMs = unixMs(pass.tca.julian);
    out.losMs = unixMs(pass.los.julian);
    out.maxElevation = pass.maxElevationDeg();
    const tracking::PassPlan &plan = tracker.plan();
    if (plan.isValid())
        out.plannedWorstDeg = plan.predictedWorstDeg;
    out.flipped = plan.flipped;
    out.overTheTop = plan.overTheTop;
    out.unwinds = plan.unwinds;
    const model::RotatorLimits limits = station.session()->moveGate().limits();
    out.azimuthTurnStart = limits.azMin;
    out.azimuthTurnEnd = limits.azMin + 360.0;
    for (const tracking::SkyPoint &p : tracker.skyPoints())
        out.sky.append(QPointF(p.azimuthDeg, p.elevationDeg));
    for (const tracking::PathPoint &p : plan.path)
        out.path.append(QPointF(p.azimuth, p.elevation));
    return out;
}

// The message without a field of it (a number): what says whether anything
// else changed.
QByteArray without(QByteArray message, const QByteArray &field)
{
    const QByteArray key = '"' + field + "\":";
    const int from = message.indexOf(key);
    if (from < 0)
        return message;
    int to = from + int(key.size());
    while (to < message.size() && message[to] != ',' && message[to] != '}')
        ++to;
    return message.remove(from, to - from);
}

// Without its time stamps: the station's clock moves on by itself.
QByteArray withoutTime(const QByteArray &message)
{
    return without(without(message, "unix_ms"), "clock_ms");
}

} // namespace

PlanPublisher::PlanPublisher(Station *station, const QString &stationName, Publish publish, QObject *parent)
    : QObject(parent), m_station(station), m_name(stationName), m_publish(std::move(publish))
{
    m_due.setSingleShot(true);
    m_due.setInterval(kGatherMs);
    connect(&m_due, &QTimer::timeout, this, [this] { publishChanged(false); });
    if (tracking::PassRunner *runner = m_station->passRunner()) {
        connect(&runner->tracker(), &tracking::Tracker::stateChanged, this, &PlanPublisher::changed);
        connect(runner, &tracking::PassRunner::activeChanged, this, &PlanPublisher::changed);
    }
    if (ScheduleRunner *schedule = m_station->scheduleRunner()) {
        connect(schedule, &ScheduleRunner::scheduleChanged, this, &PlanPublisher::changed);
        connect(schedule, &ScheduleRunner::currentChanged, this, &PlanPublisher::changed);
        connect(schedule, &ScheduleRunner::runningChanged, this, &PlanPublisher::changed);
    }
}

void PlanPublisher::setEnabled(bool on)
{
    m_enabled = on;
    if (!on)
        m_due.stop();
}

void PlanPublisher::changed()
{
    if (m_enabled && !m_due.isActive())
        m_due.start();
}

void PlanPublisher::publishNow()
{
    publishChanged(true);
}

QByteArray PlanPublisher::planMessage() const
{
    return remote::encodeStationPlan(planNow(*m_station, QDateTime::currentMSecsSinceEpoch()));
}

QByteArray PlanPublisher::scheduleMessage() const
{
    const ScheduleRunner *runner = m_station->scheduleRunner();
    static const schedule::Schedule none;
    const bool running = runner && runner->isRunning();
    const tracking::StationClock *clock = m_station->clock();
    return remote::encodeStationSchedule(QDateTime::currentMSecsSinceEpoch(), unixMs(clock->nowJulian()), clock->rate(),
                                         running,
                                         running ? runner->schedule() : none,
                                         running ? runner->current() : std::nullopt);
}

void PlanPublisher::publishChanged(bool always)
{
    if (!m_enabled)
        return;
    m_due.stop();
    const QByteArray plan = planMessage();
    if (always || withoutTime(plan) != m_lastPlan) {
        m_lastPlan = withoutTime(plan);
        ++m_plans;
        m_publish({remote::stationTopic(m_name, remote::StationTopic::Plan), plan, 1, true});
    }
    const QByteArray schedule = scheduleMessage();
    if (always || withoutTime(schedule) != m_lastSchedule) {
        m_lastSchedule = withoutTime(schedule);
        ++m_schedules;
        m_publish({remote::stationTopic(m_name, remote::StationTopic::Schedule), schedule, 1, true});
    }
}

} // namespace slew::station
