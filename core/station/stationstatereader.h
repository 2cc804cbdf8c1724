// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The state and telemetry of the Station in this process, as the values a
// face shows (face/stationstate.h, face/telemetrysample.h): read off the
// first rotor's session and alarms, the pass runner, the clock and the
// radio, and said to have changed whenever one of them says so. The window's
// face (localstationface.h) and what the station publishes on a broker
// (statepublisher.h) both read the station through this, so the two say the
// same thing in the same words.

#include "face/stationstate.h"
#include "face/telemetrysample.h"

#include <QObject>

namespace slew::station {

class Station;

class StationStateReader : public QObject {
    Q_OBJECT
public:
    explicit StationStateReader(Station *station, QObject *parent = nullptr);

    // The state as it is now.
    face::StationState state() const;
    // The telemetry as last known.
    const face::TelemetrySample &sample() const { return m_sample; }
    // The pointing and Doppler errors are measured now and then: one who
    // passes a sample on forgets them, so each is passed on once, not
    // repeated as if measured again.
    void forgetMeasurements();

signals:
    // `readingsOnly`: nothing but readings that change all the time have
    // changed: where the antenna points (each poll says so, moved or not),
    // the radio's frequencies (many times a second during a pass).
    void stateChanged(bool readingsOnly);
    void telemetryChanged();

private:
    Station *m_station;
    std::optional<QPointF> m_target; // the target shown; cleared as the window clears it
    QString m_linkDetail;            // why the link is down, when it is
    std::optional<quint16> m_status; // the last status word, when valid
    face::TelemetrySample m_sample;
};

} // namespace slew::station
