// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a station says on the broker about itself: its state
// (remote/stationstate.h, retained) whenever it changes, at most five
// times a second and at least every kHeartbeatMs, and its telemetry
// (remote/stationtelemetry.h) at most at the rotator's poll rate. Changes
// that come together go out as one message. While the antenna only moves,
// or the radio is only tuned (a pass's Doppler), the state follows once a
// second: the telemetry carries the position at the poll rate, and every
// message costs the station a wake-up or two. It
// reads the Station as the window's face does (stationstatereader.h) and
// hands each message to `publish`.

#include "remote/mqttsettings.h"
#include "remote/stationstate.h"
#include "remote/stationtelemetry.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <functional>

namespace slew::station {

class Station;
class StationStateReader;

class StatePublisher : public QObject {
    Q_OBJECT
public:
    static constexpr int kMinStateIntervalMs = 200;
    static constexpr int kPositionStateIntervalMs = 1000;
    static constexpr int kHeartbeatMs = 5000;

    using Publish = std::function<void(const remote::MqttMessage &)>;
    StatePublisher(Station *station, const QString &stationName, Publish publish, QObject *parent = nullptr);

    // The state as it is now.
    face::StationState state() const;
    // Publishes the state now (a new connection, a goodbye).
    void publishState();
    void setEnabled(bool on);

    int statesPublished() const { return m_states; }
    int telemetryPublished() const { return m_samples; }

private:
    // `readingsOnly`: nothing but where the antenna points or the radio's
    // frequencies have changed.
    void stateChanged(bool readingsOnly = false);
    void telemetryChanged();
    void publishTelemetry();
    void follow();

    Station *m_station;
    StationStateReader *m_reader; // what the state and telemetry say
    QString m_name;
    Publish m_publish;
    bool m_enabled = false;
    std::optional<face::StationState> m_published; // the last state sent
    QTimer m_stateDue, m_telemetryDue, m_heartbeat;
    QElapsedTimer m_sinceState, m_sinceTelemetry;
    int m_states = 0, m_samples = 0;
};

} // namespace slew::station
