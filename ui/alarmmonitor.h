#pragma once
// Turns what the session reports into alarms the operator must see (GE error
// bits, GS axis errors, end stops, a lost link, stale position) and into a
// stream of timestamped events. Alarms are keyed, so a condition that holds
// raises one alarm, and it clears when the condition does.

#include "session/rotatorsession.h"

#include <QDateTime>
#include <QMap>
#include <QObject>

namespace slew::ui {

class AlarmMonitor : public QObject {
    Q_OBJECT
public:
    enum class Severity { Info, Warning, Alarm };
    Q_ENUM(Severity)

    explicit AlarmMonitor(session::RotatorSession *session, QObject *parent = nullptr);

    QStringList activeAlarms() const;
    bool anySevere() const; // an alarm, not only a warning (an end stop is a warning)
    bool isActive(const QString &key) const { return m_active.contains(key); }

public slots:
    // The operator is about to disconnect: going down is not a loss.
    void expectDisconnect() { m_expectDisconnect = true; }

signals:
    void alarmsChanged(const QStringList &active, bool severe);
    void eventLogged(const QDateTime &when, slew::ui::AlarmMonitor::Severity severity, const QString &text);

private:
    void setAlarm(const QString &key, bool on, const QString &text, Severity severity = Severity::Alarm);
    void log(Severity severity, const QString &text);
    void onState(session::RotatorSession::State state, const QString &detail);
    void onTelemetry(const session::Telemetry &t);

    session::RotatorSession *m_session;
    struct Condition {
        QString text;
        Severity severity;
    };
    QMap<QString, Condition> m_active;
    session::RotatorSession::State m_state = session::RotatorSession::State::Disconnected;
    bool m_expectDisconnect = false;
};

} // namespace slew::ui
