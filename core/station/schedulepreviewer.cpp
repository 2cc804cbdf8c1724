// SPDX-License-Identifier: GPL-3.0-or-later
#include "schedulepreviewer.h"

#include "schedulerequestoptions.h"
#include "schedulerunner.h"
#include "station.h"
#include "targetbyname.h"

#include "tracking/rotatorreach.h"

#include <QFutureWatcher>
#include <QtConcurrent/QtConcurrentRun>

namespace slew::station {

SchedulePreviewer::SchedulePreviewer(Station *station, const QList<sky::ElementSet> &given, QObject *parent)
    : QObject(parent), m_station(station), m_given(given)
{
}

SchedulePreviewer::~SchedulePreviewer()
{
    if (m_stop)
        m_stop->store(true);
}

void SchedulePreviewer::letGo(const QString &why)
{
    ++m_generation;
    if (m_stop)
        m_stop->store(true);
    m_stop.reset();
    if (!m_pendingId.isNull())
        emit refused(std::exchange(m_pendingId, QString()), why);
}

void SchedulePreviewer::preview(const QString &id, const QStringList &targets, const face::ScheduleRequest &request)
{
    letGo(tr("a newer preview was asked"));
    const ScheduleOptions options = scheduleOptions(request);
    if (const QString refusal = m_station->passRunner() ? scheduleOptionsFault(options) : m_station->error();
        !refusal.isEmpty()) {
        emit refused(id, refusal);
        return;
    }
    face::SchedulePreview named;
    QList<tracking::TrackTarget> found;
    for (const QString &text : targets) {
        face::NamedTarget t;
        t.asked = text.trimmed();
        QString why;
        if (const std::optional<tracking::TrackTarget> target = targetByName(*m_station, m_given, t.asked, &why)) {
            t.name = target->name();
            if (target->kind == tracking::TrackTarget::Kind::Satellite)
                t.norad = target->elements.catalogueNumber;
            found.append(*target);
        } else {
            t.problem = why;
        }
        named.targets.append(t);
    }
    // Named without a place; planned only with one.
    if (!m_station->place()) {
        named.notPlanned = tr("a schedule needs the station's place");
        emit previewed(id, named);
        return;
    }
    const schedule::ScheduleSettings settings = scheduleSettingsNow(
        *m_station->session(), *m_station->passRunner(), *m_station->clock(), options);
    const tracking::RotatorReach reach = tracking::reachOf(*m_station->session());
    m_pendingId = id;
    m_stop = std::make_shared<std::atomic<bool>>(false);
    const int generation = ++m_generation;
    auto *watcher = new QFutureWatcher<schedule::Schedule>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, generation, named]() mutable {
        watcher->deleteLater();
        if (generation != m_generation)
            return; // let go, and answered then
        m_stop.reset();
        named.schedule = watcher->result();
        emit previewed(std::exchange(m_pendingId, QString()), named);
    });
    watcher->setFuture(QtConcurrent::run([found, place = *m_station->place(), reach, settings, stop = m_stop] {
        return schedule::planSchedule(found, place, reach, settings, {}, stop.get());
    }));
}

} // namespace slew::station
