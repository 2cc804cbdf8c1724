#pragma once
// Writes what the session reports into a TelemetryHistory: position, the
// commanded position (CR10/CR11), speed, load, temperature, and the status
// and error registers; and, while Slew tracks, the pointing error the
// tracker measures and the Doppler error the radio measures on each path.
// Recording goes on while the charts are paused.

#include "model/telemetryhistory.h"
#include "remote/stationtelemetry.h"
#include "session/rotatorsession.h"

#include <QObject>

#include <array>

namespace slew::ui {

class TelemetryRecorder : public QObject {
    Q_OBJECT
public:
    enum Series {
        AzActual, ElActual, AzCommanded, ElCommanded, AzVelocity, ElVelocity,
        AzLoad, ElLoad, Temperature, AzStatus, ElStatus, ErrorFlags, PointingError,
        ReceiveDopplerError, TransmitDopplerError, SeriesCount
    };
    Q_ENUM(Series)

    // A telemetry value that does not change is still recorded this often,
    // so a flat line reaches the present.
    static constexpr qint64 kRepeatMs = 1000;

    // With no session, it records only what it is handed: a remote
    // station's telemetry (recordRemote).
    explicit TelemetryRecorder(session::RotatorSession *session, QObject *parent = nullptr);

    const model::TelemetryHistory &history() const { return m_history; }
    static QString seriesLabel(Series s);
    static bool isElevation(Series s)
    {
        return s == ElActual || s == ElCommanded || s == ElVelocity || s == ElLoad || s == ElStatus;
    }

public slots:
    // The angle on the sky between antenna and target, in degrees, as the
    // tracker measures it on each position while it tracks. Between passes
    // nothing is recorded: the series has a gap, not zeros.
    void recordPointingError(double degrees);
    // How far the radio is from the Doppler-corrected frequency on the
    // receive and the transmit path, in hertz (station/dopplerradio.h's
    // measured(): at most five a second); NaN for a path not tuned.
    void recordDopplerError(double receiveHz, double transmitHz);
    // One sample a station published on the broker, at the time it arrived
    // (the charts' clock is this machine's).
    void recordRemote(const slew::remote::TelemetrySample &sample);

signals:
    void recorded(); // something was added

private:
    void record(Series s, qint64 now, double value, bool onlyOnChange);
    void onTelemetry(const session::Telemetry &t);

    model::TelemetryHistory m_history;
    std::array<double, SeriesCount> m_lastValue{};
    std::array<qint64, SeriesCount> m_lastTime{};
};

} // namespace slew::ui
