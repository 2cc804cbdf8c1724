// SPDX-License-Identifier: GPL-3.0-or-later
#include "alarmmonitor.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace slew::station {

using session::RotatorSession;

namespace {

// Slower than this (deg/s) an axis is at rest: well below the slowest
// rotator's speed, well above encoder jitter.
constexpr double kMovingSpeed = 0.2;
// Travel between two telemetry reads that counts as having moved.
constexpr double kMovedDegrees = 0.2;

} // namespace

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
    connect(session, &RotatorSession::positionChanged, this, &AlarmMonitor::onPosition);
    connect(session, &RotatorSession::badFramesAlarm, this, [this](bool on, const QString &text) {
        setAlarm(QStringLiteral("checksum"), on, tr("Damaged replies: %1").arg(text));
    });
    connect(session, &RotatorSession::unreadableRepliesAlarm, this, [this](bool on, const QString &text) {
        setAlarm(QStringLiteral("unreadable"), on, tr("Unreadable replies: %1").arg(text));
    });
    // The motion guard stopped an axis and holds it: an alarm until the
    // operator clears it, which is logged with who did.
    connect(session, &RotatorSession::motionFaultChanged, this, [this](session::Axis axis, const QString &text) {
        setAlarm(axis == session::Axis::Azimuth ? QStringLiteral("motion-az") : QStringLiteral("motion-el"), true,
                 tr("%1; moves of it are held until the fault is cleared").arg(text));
    });
    connect(session, &RotatorSession::motionFaultsCleared, this, [this](const QString &who) {
        setAlarm(QStringLiteral("motion-az"), false, {});
        setAlarm(QStringLiteral("motion-el"), false, {});
        log(Severity::Info, tr("Motion fault cleared by %1: the axes may be driven again").arg(who));
    });
    connect(session, &RotatorSession::alarmReceived, this,
            [this](const QString &text) { log(Severity::Alarm, tr("Controller alarm: %1").arg(text)); });
    // A refused move goes on the banner (which logs it); other refusals, such
    // as a bad register value, only to the log.
    m_refusedMoveShown.setSingleShot(true);
    m_refusedMoveShown.setInterval(kRefusedMoveShownMs);
    auto clearRefusedMove = [this] {
        m_refusedMoveShown.stop();
        setAlarm(QStringLiteral("refused-move"), false, {});
    };
    connect(&m_refusedMoveShown, &QTimer::timeout, this, clearRefusedMove);
    connect(session, &RotatorSession::moveSent, this, clearRefusedMove);
    connect(session, &RotatorSession::moveRefused, this, [this](const QString &why) {
        m_refusedMove = why;
        setAlarm(QStringLiteral("refused-move"), true, tr("Move refused: %1").arg(why), Severity::Warning);
        m_refusedMoveShown.start();
    });
    connect(session, &RotatorSession::commandRefused, this, [this](const QString &why) {
        if (why == std::exchange(m_refusedMove, QString()))
            return; // on the banner already
        log(Severity::Warning, tr("Not sent: %1").arg(why));
    });
    connect(session, &RotatorSession::requestFailed, this, [this](const QString &request, const QString &why) {
        log(Severity::Warning, tr("%1 failed: %2").arg(request, why));
    });
    connect(session, &RotatorSession::errorOccurred, this, [this](const QString &message) {
        if (!m_stateDetail.isEmpty() && m_stateDetail.contains(message))
            return; // said with the state change
        if (m_heldErrors.isEmpty())
            QTimer::singleShot(0, this, &AlarmMonitor::flushHeldErrors);
        m_heldErrors << message;
    });
    // A controller whose position does not read (most often the wrong
    // dialect) moves nothing Slew sends: an alarm until a position comes.
    auto checkPositionRead = [this] {
        const session::Capabilities &caps = m_session->capabilities();
        const bool unread = m_session->isConnected() && caps.probed && !caps.positionFeedback && m_session->awaitingPosition();
        QString why = m_session->positionNotRead();
        if (!why.isEmpty())
            why[0] = why[0].toUpper();
        setAlarm(QStringLiteral("no-position"), unread, why);
    };
    connect(session, &RotatorSession::capabilitiesChanged, this, checkPositionRead);
    connect(session, &RotatorSession::positionChanged, this, checkPositionRead);
    connect(session, &RotatorSession::stateChanged, this, checkPositionRead);
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
        emit alarmRaised(key, text, severity);
    } else {
        if (!m_active.contains(key))
            return;
        const QString was = m_active.take(key).text;
        log(Severity::Info, tr("Cleared: %1").arg(was));
        emit alarmCleared(key, was);
    }
    emit alarmsChanged(activeAlarms(), anySevere());
}

void AlarmMonitor::flushHeldErrors()
{
    for (const QString &message : std::exchange(m_heldErrors, {}))
        log(Severity::Warning, message);
}

void AlarmMonitor::onState(RotatorSession::State state, const QString &detail)
{
    // An error held for this turn that the state's reason repeats is said
    // once, with the state.
    if (!detail.isEmpty()) {
        m_heldErrors.removeIf([&](const QString &held) { return detail.contains(held); });
        if (m_stateDetail.isEmpty())
            QTimer::singleShot(0, this, [this] { m_stateDetail.clear(); });
        m_stateDetail = detail;
    }
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
                                   QStringLiteral("endstop-az"), QStringLiteral("endstop-el"),
                                   QStringLiteral("refused-move")})
            setAlarm(key, false, {});
        setResting(0, {});
        setResting(1, {});
        m_lastPositionMs = -1;
        m_lastSwitches[0] = m_lastSwitches[1] = -1;
        break;
    }
}

void AlarmMonitor::onPosition(double az, double el, bool stale)
{
    setAlarm(QStringLiteral("stale"), stale && m_state == RotatorSession::State::Connected,
             tr("Position is stale: the controller stopped answering"));
    if (stale)
        return;
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    if (m_lastPositionMs >= 0 && now > m_lastPositionMs) {
        const double seconds = double(now - m_lastPositionMs) / 1000.0;
        m_speed[0] = (az - m_lastPosition[0]) / seconds;
        m_speed[1] = (el - m_lastPosition[1]) / seconds;
    }
    m_lastPosition[0] = az;
    m_lastPosition[1] = el;
    m_lastPositionMs = now;
}

QString AlarmMonitor::resting() const
{
    QStringList parts;
    for (const QString &r : m_resting) {
        if (!r.isEmpty())
            parts << r;
    }
    return parts.join(QStringLiteral(" · "));
}

void AlarmMonitor::setResting(int axis, const QString &text)
{
    if (m_resting[axis] == text)
        return;
    m_resting[axis] = text;
    if (!text.isEmpty())
        log(Severity::Info, text);
    emit restingChanged(resting());
}

void AlarmMonitor::onTelemetry(const session::Telemetry &t)
{
    checkEndStop(0, t.azEndStop, t.azVelocity);
    checkEndStop(1, t.elEndStop, t.elVelocity);
}

void AlarmMonitor::checkEndStop(int axis, int bits, double reportedSpeed)
{
    const bool az = axis == 0;
    const QString key = az ? QStringLiteral("endstop-az") : QStringLiteral("endstop-el");
    QStringList which;
    if (bits > 0 && (bits & 1))
        which << (az ? tr("counter-clockwise") : tr("lower"));
    if (bits > 0 && (bits & 2))
        which << (az ? tr("clockwise") : tr("upper"));
    const int before = m_lastSwitches[axis];
    const double movedBy = m_lastPosition[axis] - m_positionAtLastSwitches[axis];
    m_lastSwitches[axis] = std::max(bits, 0);
    m_positionAtLastSwitches[axis] = m_lastPosition[axis];
    if (which.isEmpty()) {
        setAlarm(key, false, {});
        setResting(axis, {});
        return;
    }
    const QString where = which.join(QStringLiteral(" and "));
    const QString name = az ? tr("Azimuth") : tr("Elevation");
    // Moving into the switch, or the switch tripped since the last look while
    // the axis travelled towards it: the drive ran (or was sent) into its
    // stop. A switch found set at rest is where many rotators park.
    const double speed = std::isfinite(reportedSpeed) ? reportedSpeed : m_speed[axis];
    const int tripped = before < 0 ? 0 : bits & ~before;
    const bool into = ((bits & 1) && speed < -kMovingSpeed) || ((bits & 2) && speed > kMovingSpeed)
        || ((tripped & 1) && movedBy < -kMovedDegrees) || ((tripped & 2) && movedBy > kMovedDegrees);
    if (into || isActive(key)) {
        setResting(axis, {});
        setAlarm(key, true, tr("%1 ran into its %2 end stop").arg(name, where), Severity::Warning);
    } else {
        setResting(axis, tr("%1 rests on its %2 limit switch").arg(name, where));
    }
}

} // namespace slew::station
