// SPDX-License-Identifier: GPL-3.0-or-later
#include "stationstatereader.h"

#include "alarmmonitor.h"
#include "dopplerradio.h"
#include "station.h"
#include "trackingnow.h"

#include "protocol/dialect.h"
#include "session/rotatorsession.h"
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

// The radio's link in the rotator's words: a lost link being opened again
// is reconnecting, as the rotator's is.
QString radioLinkName(const DopplerRadio &radio)
{
    if (!radio.link())
        return QStringLiteral("none");
    const bool again = radio.isWanted() && radio.reopenAttempts() > 0;
    switch (radio.link()->state()) {
    case radio::RadioLink::State::Open:
        return QStringLiteral("connected");
    case radio::RadioLink::State::Opening:
        return again ? QStringLiteral("reconnecting") : QStringLiteral("connecting");
    default:
        return again ? QStringLiteral("reconnecting") : QStringLiteral("disconnected");
    }
}

std::optional<double> known(double value)
{
    return std::isfinite(value) ? std::optional<double>(value) : std::nullopt;
}

} // namespace

StationStateReader::StationStateReader(Station *station, QObject *parent) : QObject(parent), m_station(station)
{
    RotatorSession *s = m_station->session();
    const auto state = [this] { emit stateChanged(false); };
    connect(s, &RotatorSession::stateChanged, this, state);
    connect(s, &RotatorSession::profileChanged, this, state);
    connect(s, &RotatorSession::parkChanged, this, state);
    connect(s, &RotatorSession::versionChanged, this, state);
    connect(s, &RotatorSession::capabilitiesChanged, this, state);
    connect(s, &RotatorSession::targetChanged, this, [this](double az, double el) {
        m_target = QPointF(az, el);
        emit stateChanged(false);
    });
    connect(s, &RotatorSession::targetCleared, this, [this] {
        m_target.reset();
        emit stateChanged(false);
    });
    connect(s, &RotatorSession::stateChanged, this, [this](RotatorSession::State st, const QString &detail) {
        if (st == RotatorSession::State::Connecting)
            m_target.reset();
        m_linkDetail = st == RotatorSession::State::Connected ? QString() : detail;
    });
    connect(s, &RotatorSession::positionChanged, this, [this](double az, double el) {
        m_sample.az = known(az);
        m_sample.el = known(el);
        emit stateChanged(true);
        emit telemetryChanged();
    });
    connect(s, &RotatorSession::statusChanged, this, [this](session::StatusWord w) {
        if (w.valid)
            m_sample.gs = w.raw;
        // The state carries each axis' status in words: a change of any bit
        // is a change of the state (moving, pointing, an error).
        const std::optional<quint16> status = w.valid ? std::optional<quint16>(w.raw) : std::nullopt;
        if (status != m_status) {
            m_status = status;
            emit stateChanged(false);
        }
        emit telemetryChanged();
    });
    connect(s, &RotatorSession::errorFlagsChanged, this, [this](int flags) {
        m_sample.ge = flags;
        emit stateChanged(false); // homing_failed
        emit telemetryChanged();
    });
    connect(s, &RotatorSession::commandedChanged, this, [this](double az, double el) {
        m_sample.commandedAz = known(az);
        m_sample.commandedEl = known(el);
        emit telemetryChanged();
    });
    connect(s, &RotatorSession::telemetryChanged, this, [this](const session::Telemetry &t) {
        m_sample.azSpeed = known(t.azVelocity);
        m_sample.elSpeed = known(t.elVelocity);
        m_sample.azLoad = known(t.azLoad);
        m_sample.elLoad = known(t.elLoad);
        m_sample.temperature = known(t.temperature);
        emit telemetryChanged();
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
            emit telemetryChanged();
        });
    }
    if (DopplerRadio *radio = m_station->radio()) {
        connect(radio, &DopplerRadio::measured, this, [this](double rx, double tx) {
            m_sample.dopplerRxError = known(rx);
            m_sample.dopplerTxError = known(tx);
            emit telemetryChanged();
        });
        connect(radio, &DopplerRadio::linkChanged, this, state);
        connect(radio, &DopplerRadio::linkStateChanged, this, state);
        connect(radio, &DopplerRadio::reopenScheduled, this, state);
        connect(radio, &DopplerRadio::controlHeldChanged, this, state);
        connect(radio, &DopplerRadio::steeringChanged, this, state);
        // During a pass the frequencies change many times a second, as the
        // position does while the antenna moves: a reading, not an event.
        connect(radio, &DopplerRadio::frequenciesChanged, this, [this] { emit stateChanged(true); });
    }
}

void StationStateReader::forgetMeasurements()
{
    m_sample.pointingError.reset();
    m_sample.dopplerRxError.reset();
    m_sample.dopplerTxError.reset();
}

face::StationState StationStateReader::state() const
{
    const RotatorSession *s = m_station->session();
    face::StationState out;
    out.unixMs = QDateTime::currentMSecsSinceEpoch();
    if (const tracking::StationClock *clock = m_station->clock(); clock->isRehearsal()) {
        out.clockMs = face::unixMsOfJulian(clock->nowJulian());
        out.clockRate = clock->isPaused() ? 0.0 : clock->rate();
    }
    out.link = linkName(s->state());
    out.linkDetail = m_linkDetail.left(400);
    if (s->hasPosition())
        out.position = QPointF(s->azimuth(), s->elevation());
    out.stale = s->positionStale() || !s->isConnected();
    out.target = m_target;
    out.moving = s->status().anyMoving();
    if (const session::StatusWord status = s->status(); status.valid && s->isConnected()) {
        out.azimuthStatus = session::describeAxisStatus(status.azimuth());
        if (status.isPerAxis())
            out.elevationStatus = session::describeAxisStatus(status.elevation());
        out.axisError = status.anyError();
    }
    const int errors = s->errorFlags();
    out.homingFailed = s->isConnected() && errors > 1 && (errors & session::ErrorHoming);
    if (s->isConnected() && errors > 1)
        out.controllerErrors = session::describeErrorFlags(errors).left(400);
    out.limits = s->moveGate().limits();
    out.profileLimits = s->moveGate().profileLimits();
    if (s->parkKnown())
        out.park = QPointF(s->parkAzimuth(), s->parkElevation());
    out.azimuthOnly = s->isAzimuthOnly();
    const protocol::Dialect dialect = s->profile().dialect;
    out.dialect = protocol::dialectName(dialect).left(60);
    const session::Capabilities &caps = s->capabilities();
    out.probed = caps.probed;
    out.jogSpeed = !caps.probed || caps.velocity;
    out.canHome = !caps.probed || caps.reset;
    out.parkCommand = protocol::dialectSupports(dialect, protocol::Op::Park);
    if (const face::TrackingNow followed = trackingNow(m_station->passRunner());
        followed.phase != face::TrackingNow::Phase::Off) {
        out.tracking = face::phaseWord(followed.phase);
        out.trackingTarget = followed.target.left(100);
        out.trackingNorad = followed.norad;
        if (followed.pass) {
            out.passAosMs = face::unixMsOfJulian(followed.pass->aos.julian);
            out.passLosMs = face::unixMsOfJulian(followed.pass->los.julian);
            out.passMaxElevation = followed.pass->maxElevationDeg();
        }
    }
    for (const QString &alarm : m_station->alarms()->activeAlarms().mid(0, face::kMostAlarms))
        out.alarms << alarm.left(400);
    out.severe = m_station->alarms()->anySevere();
    out.operatorHold = m_station->operatorHolds();
    out.motionHeld = m_station->session()->hasMotionFault();
    out.controllerVersion = s->version().left(100);
    out.slewVersion = QCoreApplication::applicationVersion().left(40);
    if (const DopplerRadio *radio = m_station->radio()) {
        out.radioLink = radioLinkName(*radio);
        out.radioHeld = radio->isControlHeld();
        out.radioSteering = radio->isSteering();
        out.radioReceiveHz = radio->frequencies().receiveHz;
        out.radioTransmitHz = radio->frequencies().transmitHz;
    }
    return out;
}

} // namespace slew::station
