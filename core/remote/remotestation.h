// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A station that lives on a broker, as a window sees it (the station's
// face, face/stationface.h, over MQTT): what it last said (its retained
// state, plan and schedule, its telemetry, whether it is online) and how
// old that is, and the operator's intent sent to it as commands
// (remotecommand.h). Each intent is Awaiting once sent, and answered (by
// the station on its reply topic, or by its silence) as `answered`.
//
// A jog is a lease renewed here every kJogRenewMs for kJogLeaseMs while the
// operator holds the button; if this window, its machine or the network
// goes, the station stops the rotator by itself within a second.
//
// Nothing from the broker is trusted: a message that fails its checks is
// dropped whole and said (a few a minute at most), and the last good state
// stays.

#include "mqttclient.h"
#include "remotecommand.h"
#include "stationplan.h"
#include "stationschedule.h"
#include "stationstate.h"
#include "stationtelemetry.h"

#include "face/stationface.h"
#include "input/logtext.h"

#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QTimer>

#include <optional>

namespace slew::remote {

class RemoteStation : public face::StationFace {
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

    // The face: the state, the plan of the pass ahead and the schedule, as
    // the station last published them; none before the first.
    QString title() const override { return m_name; }
    bool isLocal() const override { return false; }
    std::optional<face::StationState> state() const override { return m_state; }
    std::optional<face::StationPlan> plan() const override { return m_plan; }
    std::optional<face::StationSchedule> schedule() const override { return m_schedule; }
    bool isOnline() const { return m_online; }
    // The station's clock now, in Unix milliseconds: the wall clock, or a
    // rehearsal's time carried on from its last state at its rate. None
    // before the first state.
    std::optional<qint64> stationClockMs() const override;
    // Milliseconds since the last state arrived; -1 before the first.
    qint64 stateAgeMs() const { return m_stateAge.isValid() ? m_stateAge.elapsed() : -1; }
    // Connected to the broker, the station online, and a state not older
    // than kStaleAfterMs: what is shown is the station as it is now.
    bool isLive() const override { return m_live; }
    // Why it is not live, in words; empty when it is.
    QString whyNotLive() const override;

    // What the station's gate would say to a go-to, from the travel it
    // published: for go-to fields checked as the operator types. The
    // station's own gate has the last word.
    model::MoveCheck previewPointing(double az, double el) const override;

    // Intent. Each sends a command: Awaiting its id, or refused when it
    // could not be sent (no broker). The answer comes as answered(), and
    // as replied() with the command's name.
    face::Outcome send(RemoteCommand command);
    face::Outcome gotoPosition(double az, double el) override;
    // The station logs its own cause ("a stop over MQTT").
    face::Outcome stop(const QString &cause = {}) override;
    face::Outcome park() override;
    face::Outcome home() override;
    face::Outcome track(const QString &target, double minElevationDeg = 0) override;
    face::Outcome untrack() override;
    face::Outcome runSchedule(const QStringList &targets, const face::ScheduleRequest &request) override;
    face::Outcome stopSchedule() override;
    face::Outcome previewSchedule(const QStringList &targets, const face::ScheduleRequest &request) override;
    face::Outcome holdRadio(bool held) override;
    face::Outcome clearMotionFaults() override;
    // Turns at these speeds (°/s, signed) until endJog(), renewing the lease.
    face::Outcome startJog(double azSpeed, double elSpeed) override;
    // The station logs its own cause.
    void endJog(const QString &cause = {}) override;
    bool isJogging() const { return m_jogRenew.isActive(); }

    int statesReceived() const { return m_statesReceived; }
    int messagesRefused() const { return m_refused; }

signals:
    void onlineChanged(bool online);
    // The station's answer to a command this window sent, with the
    // command's name (answered() carries the same answer by id).
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
    // A new state whose clock is not the one carried on (a rehearsal set,
    // started or paused; the first state): predictions are out of date.
    bool clockJumped(const face::StationState &next) const;
    void renewJog();
    void expireReplies();
    void fail(const QString &id, const QString &command, const QString &why);

    QString m_name;
    std::unique_ptr<MqttClient> m_client;
    std::optional<face::StationState> m_state;
    std::optional<face::StationPlan> m_plan;
    std::optional<face::StationSchedule> m_schedule;
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
