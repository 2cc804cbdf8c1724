// SPDX-License-Identifier: GPL-3.0-or-later
#include "statepublisher.h"

#include "alarmmonitor.h"
#include "dopplerradio.h"
#include "station.h"
#include "trackingnow.h"

#include "remote/stationtopics.h"
#include "session/rotatorsession.h"
#include "sky/utctime.h"
#include "tracking/passrunner.h"
#include "tracking/stationclock.h"

#include <QCoreApplication>
#include <QDateTime>

#include <cmath>

namespace slew::station {

using session::RotatorSession;

namespace {

QString linkName(RotatorSession::State state)
{
    switch (state) {
    case RotatorSession::State::Connecting:
        return QStringLiteral("connecting");
    case RotatorSession::State::Connected:
        return QStringLiteral("connected");
    case RotatorSession::State::Reconnecting:
        return QStringLiteral("reconnecting");
    default:
        return QStringLiteral("disconnected");
    }
}

qint64 julianToUnixMs(double julian)
{
    return qint64(std::llround((julian - 2440587.5) * 86400000.0));
}

std::optional<double> known(double value)
{
    return std::isfinite(value) ? std::optional<double>(value) : std::nullopt;
}

// A timer that publishes no sooner than `minMs` after the last time; one
// already due sooner is left as it is.
void schedule(QTimer &due, const QElapsedTimer &since, int minMs)
{
    const qint64 elapsed = since.isValid() ? since.elapsed() : minMs;
    const int wait = int(std::max<qint64>(0, minMs - elapsed));
    if (due.isActive() && due.remainingTime() <= wait)
        return;
    due.start(wait);
}

} // namespace

StatePublisher::StatePublisher(Station *station, const QString &stationName, Publish publish, QObject *parent)
    : QObject(parent), m_station(station), m_name(stationName), m_publish(std::move(publish))
{
    m_stateDue.setSingleShot(true);
    m_telemetryDue.setSingleShot(true);
    connect(&m_stateDue, &QTimer::timeout, this, &StatePublisher::publishState);
    connect(&m_telemetryDue, &QTimer::timeout, this, &StatePublisher::publishTelemetry);
    m_heartbeat.setInterval(kHeartbeatMs);
    connect(&m_heartbeat, &QTimer::timeout, this, &StatePublisher::publishState);
    follow();
}

void StatePublisher::follow()
{
    RotatorSession *s = m_station->session();
    const auto state = [this] { stateChanged(); };
    connect(s, &RotatorSession::stateChanged, this, state);
    connect(s, &RotatorSession::profileChanged, this, state);
    connect(s, &RotatorSession::parkChanged, this, state);
    connect(s, &RotatorSession::versionChanged, this, state);
    connect(s, &RotatorSession::targetChanged, this, [this](double az, double el) {
        m_target = QPointF(az, el);
        stateChanged();
    });
    connect(s, &RotatorSession::targetCleared, this, [this] {
        m_target.reset();
        stateChanged();
    });
    connect(s, &RotatorSession::stateChanged, this, [this](RotatorSession::State st, const QString &detail) {
        if (st == RotatorSession::State::Connecting)
            m_target.reset();
        m_linkDetail = st == RotatorSession::State::Connected ? QString() : detail;
    });
    connect(s, &RotatorSession::positionChanged, this, [this](double az, double el, bool stale) {
        m_sample.az = known(az);
        m_sample.el = known(el);
        // Each poll says where the antenna is, moved or not: at rest the
        // heartbeat is enough for the state.
        if (!m_published || std::abs(az - m_published->position.value_or(QPointF()).x()) >= 0.005
            || std::abs(el - m_published->position.value_or(QPointF()).y()) >= 0.005 || stale != m_published->stale
            || !m_published->position)
            stateChanged(true);
        telemetryChanged();
    });
    connect(s, &RotatorSession::statusChanged, this, [this](session::StatusWord w) {
        if (w.valid)
            m_sample.gs = w.raw;
        if (w.anyMoving() != m_moving) {
            m_moving = w.anyMoving();
            stateChanged();
        }
        telemetryChanged();
    });
    connect(s, &RotatorSession::errorFlagsChanged, this, [this](int flags) {
        m_sample.ge = flags;
        telemetryChanged();
    });
    connect(s, &RotatorSession::commandedChanged, this, [this](double az, double el) {
        m_sample.commandedAz = known(az);
        m_sample.commandedEl = known(el);
        telemetryChanged();
    });
    connect(s, &RotatorSession::telemetryChanged, this, [this](const session::Telemetry &t) {
        m_sample.azSpeed = known(t.azVelocity);
        m_sample.elSpeed = known(t.elVelocity);
        m_sample.azLoad = known(t.azLoad);
        m_sample.elLoad = known(t.elLoad);
        m_sample.temperature = known(t.temperature);
        telemetryChanged();
    });
    connect(m_station->alarms(), &AlarmMonitor::alarmsChanged, this, state);
    connect(m_station, &Station::trackingChanged, this, state);
    connect(m_station, &Station::operatorHoldChanged, this, state);
    // A rehearsal started, paused, stepped or ended: viewers count by it.
    const tracking::StationClock *clock = m_station->clock();
    connect(clock, &tracking::StationClock::changed, this, state);
    connect(clock, &tracking::StationClock::pausedChanged, this, state);
    connect(clock, &tracking::StationClock::stepped, this, state);
    if (tracking::PassRunner *runner = m_station->passRunner()) {
        connect(&runner->tracker(), &tracking::Tracker::stateChanged, this, state);
        connect(&runner->tracker(), &tracking::Tracker::pointingError, this, [this](double degrees) {
            m_sample.pointingError = known(degrees);
            telemetryChanged();
        });
    }
    if (DopplerRadio *radio = m_station->radio()) {
        connect(radio, &DopplerRadio::measured, this, [this](double rx, double tx) {
            m_sample.dopplerRxError = known(rx);
            m_sample.dopplerTxError = known(tx);
            telemetryChanged();
        });
    }
}

void StatePublisher::setEnabled(bool on)
{
    m_enabled = on;
    if (on) {
        m_heartbeat.start();
    } else {
        m_heartbeat.stop();
        m_stateDue.stop();
        m_telemetryDue.stop();
    }
}

void StatePublisher::stateChanged(bool positionOnly)
{
    if (m_enabled)
        schedule(m_stateDue, m_sinceState, positionOnly ? kPositionStateIntervalMs : kMinStateIntervalMs);
}

void StatePublisher::telemetryChanged()
{
    if (m_enabled)
        schedule(m_telemetryDue, m_sinceTelemetry, std::max(50, m_station->session()->pollIntervalMs()));
}

remote::StationState StatePublisher::state() const
{
    const RotatorSession *s = m_station->session();
    remote::StationState out;
    out.unixMs = QDateTime::currentMSecsSinceEpoch();
    if (const tracking::StationClock *clock = m_station->clock(); clock->isRehearsal()) {
        out.clockMs = julianToUnixMs(clock->nowJulian());
        out.clockRate = clock->isPaused() ? 0.0 : clock->rate();
    }
    out.link = linkName(s->state());
    out.linkDetail = m_linkDetail.left(400);
    if (s->hasPosition())
        out.position = QPointF(s->azimuth(), s->elevation());
    out.stale = s->positionStale() || !s->isConnected();
    out.target = m_target;
    out.moving = s->status().anyMoving();
    out.limits = s->moveGate().limits();
    if (s->parkKnown())
        out.park = QPointF(s->parkAzimuth(), s->parkElevation());
    out.azimuthOnly = s->isAzimuthOnly();
    if (const TrackingNow followed = trackingNow(m_station->passRunner()); followed.phase != TrackingNow::Phase::Off) {
        out.tracking = phaseWord(followed.phase);
        out.trackingTarget = followed.target.left(100);
        out.trackingNorad = followed.norad;
        if (followed.pass) {
            out.passAosMs = julianToUnixMs(followed.pass->aos.julian);
            out.passLosMs = julianToUnixMs(followed.pass->los.julian);
            out.passMaxElevation = followed.pass->maxElevationDeg();
        }
    }
    for (const QString &alarm : m_station->alarms()->activeAlarms().mid(0, remote::kMostAlarms))
        out.alarms << alarm.left(400);
    out.severe = m_station->alarms()->anySevere();
    out.operatorHold = m_station->operatorHolds();
    out.controllerVersion = s->version().left(100);
    out.slewVersion = QCoreApplication::applicationVersion().left(40);
    return out;
}

void StatePublisher::publishState()
{
    if (!m_enabled)
        return;
    m_stateDue.stop();
    m_sinceState.start();
    m_heartbeat.start(); // the next beat counts from this message
    ++m_states;
    m_published = state();
    m_publish({remote::stationTopic(m_name, remote::StationTopic::State), remote::encodeStationState(*m_published), 1, true});
}

void StatePublisher::publishTelemetry()
{
    if (!m_enabled)
        return;
    m_sinceTelemetry.start();
    m_sample.unixMs = QDateTime::currentMSecsSinceEpoch();
    ++m_samples;
    m_publish({remote::stationTopic(m_name, remote::StationTopic::Telemetry), remote::encodeTelemetry(m_sample), 0,
               false});
    // The pointing and Doppler errors are measured now and then: each is
    // sent once, not repeated as if measured again.
    m_sample.pointingError.reset();
    m_sample.dopplerRxError.reset();
    m_sample.dopplerTxError.reset();
}

} // namespace slew::station
