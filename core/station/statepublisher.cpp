// SPDX-License-Identifier: GPL-3.0-or-later
#include "statepublisher.h"

#include "station.h"
#include "stationstatereader.h"

#include "remote/stationtopics.h"
#include "session/rotatorsession.h"

#include <QDateTime>

#include <cmath>

namespace slew::station {

namespace {

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
    : QObject(parent), m_station(station), m_reader(new StationStateReader(station, this)), m_name(stationName),
      m_publish(std::move(publish))
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
    connect(m_reader, &StationStateReader::stateChanged, this, [this](bool readingsOnly) {
        // Each poll says where the antenna is, moved or not: at rest the
        // heartbeat is enough for the state.
        if (readingsOnly && m_published && m_published->position) {
            const face::StationState now = m_reader->state();
            if (now.position && std::abs(now.position->x() - m_published->position->x()) < 0.005
                && std::abs(now.position->y() - m_published->position->y()) < 0.005 && now.stale == m_published->stale
                && now.radioReceiveHz == m_published->radioReceiveHz
                && now.radioTransmitHz == m_published->radioTransmitHz)
                return;
        }
        stateChanged(readingsOnly);
    });
    connect(m_reader, &StationStateReader::telemetryChanged, this, &StatePublisher::telemetryChanged);
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

void StatePublisher::stateChanged(bool readingsOnly)
{
    if (m_enabled)
        schedule(m_stateDue, m_sinceState, readingsOnly ? kPositionStateIntervalMs : kMinStateIntervalMs);
}

void StatePublisher::telemetryChanged()
{
    if (m_enabled)
        schedule(m_telemetryDue, m_sinceTelemetry, std::max(50, m_station->session()->pollIntervalMs()));
}

face::StationState StatePublisher::state() const
{
    return m_reader->state();
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
    face::TelemetrySample sample = m_reader->sample();
    sample.unixMs = QDateTime::currentMSecsSinceEpoch();
    ++m_samples;
    m_publish({remote::stationTopic(m_name, remote::StationTopic::Telemetry), remote::encodeTelemetry(sample), 0,
               false});
    m_reader->forgetMeasurements();
}

} // namespace slew::station
