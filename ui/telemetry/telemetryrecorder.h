#pragma once
// Writes what the session reports into a TelemetryHistory: position, the
// commanded position (CR10/CR11), speed, load, temperature, and the status
// and error registers; and, while Slew tracks, the pointing error the
// tracker measures and the Doppler error the radio measures on each path.
// Recording goes on while the charts are paused.
//
// Times are the station clock's once it follows one (followClock): during a
// rehearsal the samples carry the rehearsal's own time, as the pass, the
// plot and the pass records do. The record keeps to one kind of time: when
// the clock turns between real time and a rehearsal, or starts again
// earlier than the newest sample, it starts afresh rather than draw one
// day's samples on another's axis.

#include "model/telemetryhistory.h"
#include "remote/stationtelemetry.h"
#include "session/rotatorsession.h"

#include <QObject>

#include <array>

namespace slew::tracking {
class StationClock;
}

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

    // From now on samples carry the time `clock` reads (it must outlive
    // this); with none, this machine's UTC (a remote station's charts).
    void followClock(const tracking::StationClock *clock);
    // The time a sample taken now carries, in ms since 1970 UTC: `clock`'s,
    // or this machine's when there is none. The charts' right edge too.
    static qint64 nowMs(const tracking::StationClock *clock);

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
    void recordRemote(const slew::face::TelemetrySample &sample);

signals:
    void recorded(); // something was added

private:
    qint64 nowMs() const { return nowMs(m_clock); }
    void record(Series s, qint64 now, double value, bool onlyOnChange);
    void onTelemetry(const session::Telemetry &t);
    void onClockMoved();

    const tracking::StationClock *m_clock = nullptr;
    bool m_recordsRehearsal = false; // the record's samples carry a rehearsal's time
    model::TelemetryHistory m_history;
    std::array<double, SeriesCount> m_lastValue{};
    std::array<qint64, SeriesCount> m_lastTime{};
};

} // namespace slew::ui
