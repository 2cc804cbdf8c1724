// SPDX-License-Identifier: GPL-3.0-or-later
#include "planpublisher.h"

#include "schedulerunner.h"
#include "station.h"
#include "stationplanreader.h"

#include "remote/stationplan.h"
#include "remote/stationschedule.h"
#include "remote/stationtopics.h"
#include "tracking/passrunner.h"

#include <QDateTime>

#include <cmath>

namespace slew::station {
namespace {

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
    return remote::encodeStationPlan(planNow(*m_station));
}

QByteArray PlanPublisher::scheduleMessage() const
{
    const face::StationSchedule now = scheduleNow(*m_station);
    const ScheduleRunner *runner = m_station->scheduleRunner();
    return remote::encodeStationSchedule(now.unixMs, now.clockMs, now.clockRate, now.running, now.schedule,
                                         now.running ? runner->current() : std::nullopt);
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
