// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A station that lives on a broker, as a window sees it: what it last said
// (its retained state, its telemetry, whether it is online) and how old
// that is, and the operator's intent sent to it as commands
// (remotecommand.h), each answered on its reply topic. It carries the
// surfaces a window's widgets need — position, target, travel, park,
// alarms, tracking, telemetry — as values.
//
// A jog is a lease renewed here every kJogRenewMs for kJogLeaseMs while the
// operator holds the button; if this window, its machine or the network
// goes, the station stops the rotator by itself within a second.
//
// Nothing from the broker is trusted: a message that fails its checks is
// dropped whole and said (a few a minute at most), and the last good state
// stays.

#include "model/movegate.h"
#include "mqttclient.h"
#include "remotecommand.h"
#include "stationplan.h"
#include "stationschedule.h"
#include "stationstate.h"
#include "stationtelemetry.h"

#include "input/logtext.h"

#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QTimer>

#include <optional>

namespace slew::remote {

class RemoteStation : public QObject {
    Q_OBJECT
public:
    static constexpr int kJogRenewMs = 300;
    static constexpr int kJogLeaseMs = 1000;
    // A station says its state at least every 5 s; none for this long and
    // what is shown is no longer live.
    static constexpr qint64 kStaleAfterMs = 12000;
    // A command with no reply by then is said to have none.
    static constexpr int kReplyWaitMs = 10000;

    RemoteStation(const MqttSettings &settings, const QString &stationName, QObject *parent = nullptr);
    ~RemoteStation() override;

    bool open(QString *error);
    QString name() const { return m_name; }
    // "mqtts://alice@broker.example:8883".
    QString brokerDisplay() const { return m_client->settings().broker.display(); }
    MqttClient *client() const { return m_client.get(); }

    const std::optional<StationState> &state() const { return m_state; }
    // The plan of the pass ahead and the schedule, as the station last
    // published them; none before the first.
    const std::optional<StationPlan> &plan() const { return m_plan; }
    const std::optional<StationSchedule> &schedule() const { return m_schedule; }
    bool isOnline() const { return m_online; }
    // The station's clock now, in Unix milliseconds: the wall clock, or a
    // rehearsal's time carried on from its last state at its rate. None
    // before the first state.
    std::optional<qint64> stationClockMs() const;
    // Milliseconds since the last state arrived; -1 before the first.
    qint64 stateAgeMs() const { return m_stateAge.isValid() ? m_stateAge.elapsed() : -1; }
    // Connected to the broker, the station online, and a state not older
    // than kStaleAfterMs: what is shown is the station as it is now.
    bool isLive() const { return m_live; }
    // Why it is not live, in words; empty when it is.
    QString whyNotLive() const;

    // What the station's gate would say to a go-to, from the travel it
    // published: for go-to fields checked as the operator types. The
    // station's own gate has the last word.
    model::MoveCheck previewPointing(double az, double el) const;

    // Intent. Each sends a command and returns its id, or empty (with
    // *why) when it could not be sent (no broker). Replies come as replied().
    QString send(RemoteCommand command, QString *why = nullptr);
    QString gotoPosition(double az, double el, QString *why = nullptr);
    QString stop(QString *why = nullptr);
    QString park(QString *why = nullptr);
    QString home(QString *why = nullptr);
    QString track(const QString &target, QString *why = nullptr);
    QString untrack(QString *why = nullptr);
    // Turns at these speeds (°/s, signed) until endJog(), renewing the lease.
    void startJog(double azSpeed, double elSpeed);
    void endJog();
    bool isJogging() const { return m_jogRenew.isActive(); }

    int statesReceived() const { return m_statesReceived; }
    int messagesRefused() const { return m_refused; }

signals:
    void stateChanged(const slew::remote::StationState &state);
    void telemetryReceived(const slew::remote::TelemetrySample &sample);
    void planChanged(const slew::remote::StationPlan &plan);
    void scheduleChanged(const slew::remote::StationSchedule &schedule);
    void onlineChanged(bool online);
    void liveChanged(bool live);
    // The station's answer to a command this window sent.
    void replied(const QString &id, const QString &command, bool ok, const QString &error);
    // The broker would not pass a command on (the account may only watch),
    // or none came back in time.
    void commandFailed(const QString &command, const QString &why);
    // A message from the broker failed its checks and was dropped.
    void messageRefused(const QString &what);
    void connectionChanged(slew::remote::MqttClient::State state, const QString &detail);

private:
    void onMessage(const QString &topic, const QByteArray &payload);
    void refuse(const QString &what);
    void updateLive();
    void renewJog();
    void expireReplies();

    QString m_name;
    std::unique_ptr<MqttClient> m_client;
    std::optional<StationState> m_state;
    std::optional<StationPlan> m_plan;
    std::optional<StationSchedule> m_schedule;
    bool m_online = false;
    bool m_live = false;
    QElapsedTimer m_stateAge;
    QTimer m_liveCheck;
    QTimer m_jogRenew;
    RemoteCommand m_jog;
    QString m_idPrefix;
    quint64 m_nextId = 1;
    struct Pending {
        QString command;
        QElapsedTimer sent;
    };
    QHash<QString, Pending> m_pending; // id -> what it was
    QHash<int, QString> m_publishes;   // the broker's message id -> our id
    input::LogAllowance m_refusals{5, 0.1}; // what is said of bad messages
    int m_statesReceived = 0;
    int m_refused = 0;
};

} // namespace slew::remote
