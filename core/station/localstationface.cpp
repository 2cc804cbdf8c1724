// SPDX-License-Identifier: GPL-3.0-or-later
#include "localstationface.h"

#include "schedulepreviewer.h"
#include "schedulerequestoptions.h"
#include "schedulerunner.h"
#include "station.h"
#include "stationplanreader.h"
#include "stationstatereader.h"
#include "targetbyname.h"

#include "face/trackingnow.h"
#include "session/rotatorsession.h"
#include "sky/elementsetsources.h"
#include "tracking/passrunner.h"
#include "tracking/stationclock.h"

#include <QMetaMethod>

namespace slew::station {

using face::Outcome;

namespace {

void coalesce(QTimer &due)
{
    if (!due.isActive())
        due.start();
}

} // namespace

LocalStationFace::LocalStationFace(Station *station, QObject *parent)
    : face::StationFace(parent), m_station(station), m_reader(new StationStateReader(station, this)),
      m_previewer(new SchedulePreviewer(station, {}, this))
{
    connect(m_previewer, &SchedulePreviewer::previewed, this, [this](const QString &id, const face::SchedulePreview &p) {
        emit schedulePreviewed(id, p);
        emit answered(id, Outcome::done());
    });
    connect(m_previewer, &SchedulePreviewer::refused, this,
            [this](const QString &id, const QString &why) { emit answered(id, Outcome::refused(why)); });
    connect(m_station, &Station::placeChanged, this, &face::StationFace::skyChanged);
    connect(m_station->elementSets(), &sky::ElementSetSources::setsChanged, this, &face::StationFace::skyChanged);
    connect(m_station->clock(), &tracking::StationClock::changed, this, &face::StationFace::skyChanged);
    for (QTimer *due : {&m_telemetryDue, &m_planDue}) {
        due->setSingleShot(true);
        due->setInterval(0);
    }
    connect(&m_telemetryDue, &QTimer::timeout, this, [this] {
        emit telemetryReceived(m_reader->sample());
        m_reader->forgetMeasurements();
    });
    connect(&m_planDue, &QTimer::timeout, this, [this] {
        emit planChanged(planNow(*m_station));
        emit scheduleChanged(scheduleNow(*m_station));
    });
    // The state is said at once: a widget shows what the operator just did
    // (a target set, a Stop) before the next key. Nothing is read for a face
    // nobody watches (the station service's).
    connect(m_reader, &StationStateReader::stateChanged, this, [this] {
        if (isSignalConnected(QMetaMethod::fromSignal(&face::StationFace::stateChanged)))
            emit stateChanged(m_reader->state());
    });
    connect(m_reader, &StationStateReader::telemetryChanged, this, [this] {
        if (isSignalConnected(QMetaMethod::fromSignal(&face::StationFace::telemetryReceived)))
            coalesce(m_telemetryDue);
    });
    const auto plans = [this] {
        if (isSignalConnected(QMetaMethod::fromSignal(&face::StationFace::planChanged))
            || isSignalConnected(QMetaMethod::fromSignal(&face::StationFace::scheduleChanged)))
            coalesce(m_planDue);
    };
    if (tracking::PassRunner *runner = m_station->passRunner()) {
        connect(&runner->tracker(), &tracking::Tracker::stateChanged, this, plans);
        connect(runner, &tracking::PassRunner::activeChanged, this, plans);
    }
    if (ScheduleRunner *schedule = m_station->scheduleRunner()) {
        connect(schedule, &ScheduleRunner::scheduleChanged, this, plans);
        connect(schedule, &ScheduleRunner::currentChanged, this, plans);
        connect(schedule, &ScheduleRunner::runningChanged, this, plans);
    }
}

LocalStationFace::~LocalStationFace() = default;

QString LocalStationFace::title() const
{
    return m_station->session()->uri();
}

std::optional<face::StationState> LocalStationFace::state() const
{
    return m_reader->state();
}

std::optional<face::StationPlan> LocalStationFace::plan() const
{
    return planNow(*m_station);
}

std::optional<face::StationSchedule> LocalStationFace::schedule() const
{
    return scheduleNow(*m_station);
}

std::optional<qint64> LocalStationFace::stationClockMs() const
{
    return face::unixMsOfJulian(m_station->clock()->nowJulian());
}

model::MoveCheck LocalStationFace::previewPointing(double az, double el) const
{
    return m_station->session()->previewPointing(az, el);
}

Outcome LocalStationFace::gotoPosition(double az, double el)
{
    return Outcome::refusedIf(m_station->session()->gotoPosition(az, el).refusal);
}

Outcome LocalStationFace::stop(const QString &cause)
{
    m_jogAz = m_jogEl = 0;
    return Outcome::refusedIf(m_station->stop(cause).refusal);
}

Outcome LocalStationFace::park()
{
    return Outcome::refusedIf(m_station->session()->park().refusal);
}

Outcome LocalStationFace::home()
{
    return Outcome::refusedIf(m_station->session()->home().refusal);
}

Outcome LocalStationFace::track(const QString &target, double minElevationDeg)
{
    QString why;
    const std::optional<tracking::TrackTarget> found = targetByName(*m_station, {}, target.trimmed(), &why);
    if (!found)
        return Outcome::refused(why);
    return m_station->track(*found, minElevationDeg);
}

Outcome LocalStationFace::untrack()
{
    return m_station->untrack(tr("untracked by the operator"));
}

Outcome LocalStationFace::runSchedule(const QStringList &targets, const face::ScheduleRequest &request)
{
    QString why;
    const std::optional<QList<tracking::TrackTarget>> found = targetsByName(*m_station, {}, targets, &why);
    if (!found)
        return Outcome::refused(why);
    return m_station->runSchedule(*found, scheduleOptions(request));
}

Outcome LocalStationFace::stopSchedule()
{
    return m_station->stopSchedule(tr("schedule ended by the operator"));
}

Outcome LocalStationFace::previewSchedule(const QStringList &targets, const face::ScheduleRequest &request)
{
    const QString id = QStringLiteral("preview-%1").arg(++m_lastPreview);
    // Answered after this returns, even when refused at once: the asker
    // knows the id before the answer comes.
    QMetaObject::invokeMethod(
        m_previewer, [this, id, targets, request] { m_previewer->preview(id, targets, request); }, Qt::QueuedConnection);
    return Outcome::awaiting(id);
}

Outcome LocalStationFace::clearMotionFaults()
{
    return m_station->session()->clearMotionFaults(tr("the operator at the station"))
               ? Outcome::done()
               : Outcome::refused(tr("no axis is held by the motion guard"));
}

Outcome LocalStationFace::holdRadio(bool held)
{
    return m_station->holdRadio(held);
}

Outcome LocalStationFace::startJog(double azSpeed, double elSpeed)
{
    session::RotatorSession *s = m_station->session();
    // Each axis turns at its speed; an axis this jog turned and now given
    // 0 stops, the other goes on (the opposite arrow let go of). A speed
    // said again is sent again: a Stop from elsewhere may have ended it.
    const auto turn = [this, s](session::Axis axis, double speed, double &turning) -> Outcome {
        if (speed == 0 && turning == 0)
            return Outcome::done();
        if (speed == 0) {
            turning = 0;
            s->stop(tr("jog released"), axis == session::Axis::Azimuth ? session::Axes::Azimuth : session::Axes::Elevation);
            return Outcome::done();
        }
        const session::CommandResult sent = s->moveAxis(axis, speed);
        if (!sent) {
            endJog(tr("jog refused: %1").arg(sent.refusal));
            return Outcome::refused(sent.refusal);
        }
        turning = speed;
        return Outcome::done();
    };
    if (const Outcome az = turn(session::Axis::Azimuth, azSpeed, m_jogAz); az.isRefused())
        return az;
    return turn(session::Axis::Elevation, elSpeed, m_jogEl);
}

void LocalStationFace::endJog(const QString &cause)
{
    if (m_jogAz == 0 && m_jogEl == 0)
        return;
    const session::Axes axes = m_jogAz != 0 && m_jogEl != 0 ? session::Axes::Both
                               : m_jogAz != 0              ? session::Axes::Azimuth
                                                           : session::Axes::Elevation;
    m_jogAz = m_jogEl = 0;
    m_station->session()->stop(cause, axes);
}

} // namespace slew::station
