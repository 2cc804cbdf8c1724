#include "alarmmonitor.h"

#include <algorithm>

namespace slew::ui {

using session::RotatorSession;

AlarmMonitor::AlarmMonitor(RotatorSession *session, QObject *parent) : QObject(parent), m_session(session)
{
    connect(session, &RotatorSession::stateChanged, this, &AlarmMonitor::onState);
    connect(session, &RotatorSession::errorFlagsChanged, this, [this](int ge) {
        // GE 1 (or 0) is "no error" in every reading in force.
        const QString what = ge > 1 ? session::describeErrorFlags(ge) : QString();
        setAlarm(QStringLiteral("ge"), !what.isEmpty(), tr("Controller error: %1").arg(what));
    });
    connect(session, &RotatorSession::statusChanged, this, [this](session::StatusWord s) {
        QStringList axes;
        if (s.valid && (s.azimuth() & session::StatusError))
            axes << (s.isPerAxis() ? tr("azimuth") : tr("rotator"));
        if (s.valid && (s.elevation() & session::StatusError))
            axes << tr("elevation");
        setAlarm(QStringLiteral("gs"), !axes.isEmpty(), tr("Axis error (GS): %1").arg(axes.join(QStringLiteral(", "))));
    });
    connect(session, &RotatorSession::telemetryChanged, this, &AlarmMonitor::onTelemetry);
    connect(session, &RotatorSession::positionChanged, this, [this](double, double, bool stale) {
        setAlarm(QStringLiteral("stale"), stale && m_state == RotatorSession::State::Connected,
                 tr("Position is stale: the controller stopped answering"));
    });
    connect(session, &RotatorSession::alarmReceived, this,
            [this](const QString &text) { log(Severity::Alarm, tr("Controller alarm: %1").arg(text)); });
    connect(session, &RotatorSession::commandRefused, this,
            [this](const QString &why) { log(Severity::Warning, tr("Not sent: %1").arg(why)); });
    connect(session, &RotatorSession::requestFailed, this, [this](const QString &request, const QString &why) {
        log(Severity::Warning, tr("%1 failed: %2").arg(request, why));
    });
    connect(session, &RotatorSession::errorOccurred, this,
            [this](const QString &message) { log(Severity::Warning, message); });
    connect(session, &RotatorSession::versionChanged, this,
            [this](const QString &v) { log(Severity::Info, tr("Controller version: %1").arg(v)); });
}

void AlarmMonitor::log(Severity severity, const QString &text)
{
    emit eventLogged(QDateTime::currentDateTime(), severity, text);
}

QStringList AlarmMonitor::activeAlarms() const
{
    QStringList out;
    for (const Condition &c : m_active)
        out << c.text;
    return out;
}

bool AlarmMonitor::anySevere() const
{
    return std::any_of(m_active.begin(), m_active.end(), [](const Condition &c) { return c.severity == Severity::Alarm; });
}

void AlarmMonitor::setAlarm(const QString &key, bool on, const QString &text, Severity severity)
{
    if (on) {
        if (m_active.contains(key) && m_active[key].text == text)
            return;
        m_active.insert(key, Condition{text, severity});
        log(severity, text);
    } else {
        if (!m_active.contains(key))
            return;
        log(Severity::Info, tr("Cleared: %1").arg(m_active.take(key).text));
    }
    emit alarmsChanged(activeAlarms(), anySevere());
}

void AlarmMonitor::onState(RotatorSession::State state, const QString &detail)
{
    const bool wasUp = m_state == RotatorSession::State::Connected;
    m_state = state;
    switch (state) {
    case RotatorSession::State::Connected:
        m_expectDisconnect = false;
        setAlarm(QStringLiteral("link"), false, {});
        log(Severity::Info, detail.isEmpty() ? tr("Connected") : detail);
        break;
    case RotatorSession::State::Connecting:
        log(Severity::Info, detail.isEmpty() ? tr("Connecting") : detail);
        break;
    case RotatorSession::State::Reconnecting:
        setAlarm(QStringLiteral("link"), true, tr("Link lost: %1").arg(detail));
        break;
    case RotatorSession::State::Disconnected:
        if ((wasUp || m_active.contains(QStringLiteral("link"))) && !m_expectDisconnect) {
            setAlarm(QStringLiteral("link"), true, tr("Link lost: %1").arg(detail));
        } else {
            setAlarm(QStringLiteral("link"), false, {});
            log(m_expectDisconnect ? Severity::Info : Severity::Warning,
                detail.isEmpty() ? tr("Disconnected") : detail);
        }
        m_expectDisconnect = false;
        // Nothing else can be known about a rotator we do not talk to.
        for (const QString &key : {QStringLiteral("stale"), QStringLiteral("ge"), QStringLiteral("gs"),
                                   QStringLiteral("endstop-az"), QStringLiteral("endstop-el")})
            setAlarm(key, false, {});
        break;
    }
}

void AlarmMonitor::onTelemetry(const session::Telemetry &t)
{
    auto describe = [this](int bits, bool az) {
        if (bits <= 0)
            return QString();
        QStringList which;
        if (bits & 1)
            which << (az ? tr("counter-clockwise") : tr("lower"));
        if (bits & 2)
            which << (az ? tr("clockwise") : tr("upper"));
        return which.join(QStringLiteral(" and "));
    };
    const QString az = describe(t.azEndStop, true), el = describe(t.elEndStop, false);
    // Resting on a switch (parked at the stop) is normal enough to warn, not alarm.
    setAlarm(QStringLiteral("endstop-az"), !az.isEmpty(), tr("Azimuth at its %1 end stop").arg(az), Severity::Warning);
    setAlarm(QStringLiteral("endstop-el"), !el.isEmpty(), tr("Elevation at its %1 end stop").arg(el), Severity::Warning);
}

} // namespace slew::ui
