// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Turns what the session reports into alarms the operator must see (GE error
// bits, GS axis errors, an end stop hit while moving, a lost link, stale
// position) and into a stream of timestamped events. Alarms are keyed, so a
// condition that holds raises one alarm, and it clears when the condition
// does. Resting on a limit switch (parked at the stop, as many rotators are)
// is a state, not an alarm: it is reported quietly by restingChanged(). A
// move the session refused (outside the limits, or further into the stop an
// axis rests on) is a warning until the next move is sent, or for
// kRefusedMoveShownMs.

#include "session/rotatorsession.h"

#include <QDateTime>
#include <QMap>
#include <QStringList>
#include <QObject>
#include <QTimer>

namespace slew::station {

class AlarmMonitor : public QObject {
    Q_OBJECT
public:
    enum class Severity { Info, Warning, Alarm };
    Q_ENUM(Severity)

    static constexpr int kRefusedMoveShownMs = 10000;

    explicit AlarmMonitor(session::RotatorSession *session, QObject *parent = nullptr);

    QStringList activeAlarms() const;
    bool anySevere() const; // an alarm, not only a warning (an end stop is a warning)
    bool isActive(const QString &key) const { return m_active.contains(key); }
    // "Azimuth rests on its counter-clockwise limit switch", or empty.
    QString resting() const;

public slots:
    // The operator is about to disconnect: going down is not a loss.
    void expectDisconnect() { m_expectDisconnect = true; }

signals:
    void alarmsChanged(const QStringList &active, bool severe);
    void eventLogged(const QDateTime &when, slew::station::AlarmMonitor::Severity severity, const QString &text);
    void restingChanged(const QString &text);
    // One alarm or warning came or went: the station service logs these,
    // in the banner's words. `key` names the condition ("link", "ge", "gs",
    // "stale", "endstop-…", "checksum", "unreadable", "no-position",
    // "refused-move").
    void alarmRaised(const QString &key, const QString &text, slew::station::AlarmMonitor::Severity severity);
    void alarmCleared(const QString &key, const QString &text);

private:
    void setAlarm(const QString &key, bool on, const QString &text, Severity severity = Severity::Alarm);
    void log(Severity severity, const QString &text);
    void onState(session::RotatorSession::State state, const QString &detail);
    void onTelemetry(const session::Telemetry &t);
    void onPosition(double az, double el, bool stale);
    void checkEndStop(int axis, int bits, double reportedSpeed);
    void setResting(int axis, const QString &text);

    session::RotatorSession *m_session;
    struct Condition {
        QString text;
        Severity severity;
    };
    QMap<QString, Condition> m_active;
    session::RotatorSession::State m_state = session::RotatorSession::State::Disconnected;
    bool m_expectDisconnect = false;
    // The session reports a link that fails both as an error and as the
    // state change's reason. The error is held until the event loop turns,
    // and dropped if a state change said it meanwhile: one line, not two.
    void flushHeldErrors();
    QStringList m_heldErrors;
    QString m_stateDetail; // the last state change's reason, until the loop turns

    // Per axis (0 azimuth, 1 elevation): speed from the last two fresh
    // positions, for controllers that do not report it, and the quiet state.
    double m_lastPosition[2] = {0.0, 0.0};
    qint64 m_lastPositionMs = -1;
    double m_speed[2] = {0.0, 0.0};
    // What the last telemetry showed: switch bits (-1 unknown) and where the
    // axis was then, to tell a switch that tripped on the way from one that
    // was already set.
    int m_lastSwitches[2] = {-1, -1};
    double m_positionAtLastSwitches[2] = {0.0, 0.0};
    QString m_resting[2];
    // The refused move on show, and when it goes.
    QString m_refusedMove;
    QTimer m_refusedMoveShown;
};

} // namespace slew::station
