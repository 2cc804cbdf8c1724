// SPDX-License-Identifier: GPL-3.0-or-later
#include "stationplanreader.h"

#include "schedulerunner.h"
#include "station.h"

#include "face/trackingnow.h"
#include "session/rotatorsession.h"
#include "tracking/passrunner.h"
#include "tracking/stationclock.h"

#include <QDateTime>

#include <cmath>

namespace slew::station {
face::StationPlan planNow(const Station &station)
{
    face::StationPlan out;
    out.unixMs = QDateTime::currentMSecsSinceEpoch();
    const tracking::PassRunner *runner = station.passRunner();
    if (!runner || !runner->isRunning() || !runner->pass())
        return out;
    const tracking::Tracker &tracker = runner->tracker();
    if (tracker.state() != tracking::Tracker::State::Waiting && tracker.state() != tracking::Tracker::State::Tracking)
        return out;
    const sky::Pass &pass = *runner->pass();
    out.target = runner->target().name().left(100);
    out.norad = pass.catalogueNumber;
    out.aosMs = face::unixMsOfJulian(pass.aos.julian);
    out.tcaMs = face::unixMsOfJulian(pass.tca.julian);
    out.losMs = face::unixMsOfJulian(pass.los.julian);
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

face::StationSchedule scheduleNow(const Station &station)
{
    face::StationSchedule out;
    out.unixMs = QDateTime::currentMSecsSinceEpoch();
    const tracking::StationClock *clock = station.clock();
    out.clockMs = face::unixMsOfJulian(clock->nowJulian());
    out.clockRate = clock->rate();
    const ScheduleRunner *runner = station.scheduleRunner();
    if (!runner || !runner->isRunning())
        return out;
    out.running = true;
    out.schedule = runner->schedule();
    out.planned = out.schedule.settings.startJulian > 0;
    out.current = face::followedIndex(out.schedule, runner->current());
    return out;
}

} // namespace slew::station
