// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One connection to an MQTT broker (libmosquitto, MQTT 5, TLS), as a
// QObject on the event loop's thread: what it hears arrives as signals, and
// nothing it does blocks (the library runs on a thread of its own:
// mosquittothread.h). It connects again by itself after a failure or a
// loss, with a growing wait, and subscribes again to what it was asked.
//
// The broker decides what each account may do (its access list): a
// publish it refuses comes back as publishRefused() (MQTT 5's PUBACK), a
// subscription as subscriptionRefused().

#include "mqttsettings.h"

#include <QObject>
#include <QHash>
#include <QStringList>
#include <QTimer>

#include <memory>
#include <optional>

namespace slew::remote {

class MosquittoThread;

class MqttClient : public QObject {
    Q_OBJECT
public:
    enum class State { Idle, Connecting, Connected, Reconnecting, Closed };
    Q_ENUM(State)

    // How long close() waits for the last message and the goodbye to leave
    // before it gives up on a broker that does not take them.
    static constexpr int kCloseWaitMs = 2000;

    explicit MqttClient(const MqttSettings &settings, QObject *parent = nullptr);
    ~MqttClient() override;

    const MqttSettings &settings() const { return m_settings; }
    State state() const { return m_state; }
    bool isConnected() const { return m_state == State::Connected; }
    // Why the last attempt failed or the connection was lost; empty while connected.
    QString problem() const { return m_problem; }

    // Starts connecting. False, with *error, if the settings cannot be used.
    bool open(QString *error);
    // Sent only while connected (a station republishes its state on each
    // connection); false otherwise. `mid` is what publishRefused() will
    // name if the broker refuses it.
    bool publish(const MqttMessage &message, int *mid = nullptr);
    // Kept, and made again after each reconnection.
    void subscribe(const QString &filter, int qos = 1);
    // Publishes `last` (a station's online=false), disconnects cleanly so
    // the broker keeps the will to itself, and emits closed() once done or
    // after kCloseWaitMs.
    void close(const std::optional<MqttMessage> &last = std::nullopt);

    // Received messages dropped: too many waiting, or too large.
    int droppedMessages() const { return m_dropped; }

signals:
    void stateChanged(slew::remote::MqttClient::State state, const QString &detail);
    void connected();
    // Lost or failed; the next attempt is in `retryInSeconds`.
    void connectionLost(const QString &why, int retryInSeconds);
    void messageReceived(const QString &topic, const QByteArray &payload, bool retained);
    // The broker refused a message (MQTT 5's PUBACK, for QoS 1): its
    // access list does not let this account publish there.
    void publishRefused(int mid, const QString &reason);
    void subscriptionRefused(const QString &filter, const QString &reason);
    // Messages were dropped unread (a flood, or too large): said once per
    // batch, with how many.
    void messagesDropped(int count, const QString &why);
    void closed();

private:
    friend class MosquittoThread;
    // Called on this thread by the connection's thread.
    void onConnected();
    void onLost(const QString &why, int retryInSeconds);
    void onMessage(const QString &topic, const QByteArray &payload, bool retained);
    void onRefused(int mid, int reason);
    void onSubscribed(int mid, const QList<int> &granted);
    void onDropped(int count, const QString &why);
    void onFinished();
    void setState(State state, const QString &detail = {});

    MqttSettings m_settings;
    std::shared_ptr<MosquittoThread> m_thread;
    State m_state = State::Idle;
    QString m_problem;
    struct Subscription {
        QString filter;
        int qos;
    };
    QList<Subscription> m_subscriptions;
    QHash<int, QString> m_pendingSubscriptions; // mid -> filter
    QTimer m_closeWait;
    int m_dropped = 0;
};

} // namespace slew::remote
