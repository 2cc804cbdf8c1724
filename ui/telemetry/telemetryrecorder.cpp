#include "telemetry/telemetryrecorder.h"

#include "sky/skyvector.h"
#include "tracking/stationclock.h"

#include <QDateTime>

#include <cmath>

namespace slew::ui {

using session::RotatorSession;

TelemetryRecorder::TelemetryRecorder(RotatorSession *session, QObject *parent) : QObject(parent)
{
    for (int s = 0; s < SeriesCount; ++s)
        m_history.addSeries(seriesLabel(Series(s)));
    m_lastValue.fill(session::kUnknown);
    if (!session)
        return;

    connect(session, &RotatorSession::positionChanged, this, [this](double az, double el, bool stale) {
        if (stale)
            return; // a stale position is the old one again, not a new sample
        const qint64 now = nowMs();
        record(AzActual, now, az, false);
        record(ElActual, now, el, false);
        emit recorded();
    });
    connect(session, &RotatorSession::commandedChanged, this, [this](double az, double el) {
        const qint64 now = nowMs();
        record(AzCommanded, now, az, false);
        record(ElCommanded, now, el, false);
        emit recorded();
    });
    connect(session, &RotatorSession::telemetryChanged, this, &TelemetryRecorder::onTelemetry);
    connect(session, &RotatorSession::statusChanged, this, [this](session::StatusWord s) {
        if (!s.valid)
            return;
        const qint64 now = nowMs();
        record(AzStatus, now, s.azimuth(), true);
        record(ElStatus, now, s.elevation(), true);
        emit recorded();
    });
    connect(session, &RotatorSession::errorFlagsChanged, this, [this](int ge) {
        record(ErrorFlags, nowMs(), ge, true);
        emit recorded();
    });
}

void TelemetryRecorder::followClock(const tracking::StationClock *clock)
{
    m_clock = clock;
    if (!clock)
        return;
    connect(clock, &tracking::StationClock::changed, this, &TelemetryRecorder::onClockMoved, Qt::UniqueConnection);
    // A pause of real time turns it into a rehearsal, with no new start.
    connect(clock, &tracking::StationClock::pausedChanged, this, &TelemetryRecorder::onClockMoved,
            Qt::UniqueConnection);
    onClockMoved();
}

qint64 TelemetryRecorder::nowMs(const tracking::StationClock *clock)
{
    if (!clock)
        return QDateTime::currentMSecsSinceEpoch();
    return qint64(std::llround(sky::unixSecondsFromJulian(clock->nowJulian()) * 1000.0));
}

void TelemetryRecorder::onClockMoved()
{
    const bool rehearsal = m_clock->isRehearsal();
    const qint64 now = nowMs();
    bool earlier = false;
    for (int s = 0; s < SeriesCount; ++s) {
        const std::optional<QPointF> last = m_history.lastSample(s);
        earlier = earlier || (last && qint64(last->x()) > now);
    }
    const bool otherKind = rehearsal != m_recordsRehearsal;
    m_recordsRehearsal = rehearsal;
    if (!otherKind && !earlier)
        return;
    // The history keeps time in order (an earlier sample would be taken as
    // the latest): a new start earlier than the record, or another kind of
    // time, begins a new record.
    m_history.clear();
    m_lastValue.fill(session::kUnknown);
    m_lastTime.fill(0);
    emit recorded();
}

QString TelemetryRecorder::seriesLabel(Series s)
{
    switch (s) {
    case AzActual: return tr("Az");
    case ElActual: return tr("El");
    case AzCommanded: return tr("Az commanded");
    case ElCommanded: return tr("El commanded");
    case AzVelocity: return tr("Az speed");
    case ElVelocity: return tr("El speed");
    case AzLoad: return tr("Az load");
    case ElLoad: return tr("El load");
    case Temperature: return tr("Temperature");
    case AzStatus: return tr("GS az");
    case ElStatus: return tr("GS el");
    case ErrorFlags: return tr("GE");
    case PointingError: return tr("Pointing error");
    case ReceiveDopplerError: return tr("Receive Doppler error");
    case TransmitDopplerError: return tr("Transmit Doppler error");
    default: return {};
    }
}

void TelemetryRecorder::record(Series s, qint64 now, double value, bool onlyOnChange)
{
    if (!std::isfinite(value))
        return;
    const bool same = m_lastValue[s] == value;
    if (same && (onlyOnChange || now - m_lastTime[s] < kRepeatMs))
        return;
    m_lastValue[s] = value;
    m_lastTime[s] = now;
    m_history.append(s, now, value);
}

void TelemetryRecorder::recordPointingError(double degrees)
{
    record(PointingError, nowMs(), degrees, false);
    emit recorded();
}

void TelemetryRecorder::recordDopplerError(double receiveHz, double transmitHz)
{
    // A path that is not tuned is not recorded: a gap, not zeros (record()
    // skips NaN).
    const qint64 now = nowMs();
    record(ReceiveDopplerError, now, receiveHz, false);
    record(TransmitDopplerError, now, transmitHz, false);
    emit recorded();
}

void TelemetryRecorder::onTelemetry(const session::Telemetry &t)
{
    // Each IP reply re-sends the whole set; only values that moved (or have
    // not been written for a second) become samples.
    const qint64 now = nowMs();
    record(AzVelocity, now, t.azVelocity, false);
    record(ElVelocity, now, t.elVelocity, false);
    record(AzLoad, now, t.azLoad, false);
    record(ElLoad, now, t.elLoad, false);
    record(Temperature, now, t.temperature, false);
    emit recorded();
}

} // namespace slew::ui

namespace slew::ui {

void TelemetryRecorder::recordRemote(const face::TelemetrySample &s)
{
    const qint64 now = nowMs();
    const auto put = [&](Series series, const std::optional<double> &value, bool onlyOnChange = false) {
        if (value)
            record(series, now, *value, onlyOnChange);
    };
    put(AzActual, s.az);
    put(ElActual, s.el);
    put(AzCommanded, s.commandedAz);
    put(ElCommanded, s.commandedEl);
    put(AzVelocity, s.azSpeed);
    put(ElVelocity, s.elSpeed);
    put(AzLoad, s.azLoad);
    put(ElLoad, s.elLoad);
    put(Temperature, s.temperature);
    if (s.gs) {
        const session::StatusWord word{quint16(*s.gs), true};
        record(AzStatus, now, word.azimuth(), true);
        record(ElStatus, now, word.elevation(), true);
    }
    put(ErrorFlags, s.ge ? std::optional<double>(*s.ge) : std::nullopt, true);
    put(PointingError, s.pointingError);
    put(ReceiveDopplerError, s.dopplerRxError);
    put(TransmitDopplerError, s.dopplerTxError);
    emit recorded();
}

} // namespace slew::ui
