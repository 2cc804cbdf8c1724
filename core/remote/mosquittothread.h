// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// libmosquitto on a thread of its own, so nothing it does can hold up Qt's
// event loop: the name lookup, the TCP connect and the TLS handshake, the
// waits between attempts. The thread runs libmosquitto's own loop, which
// sleeps in select() on the broker's socket and a wake-up pipe (a publish
// from the event loop's thread wakes it at once), and otherwise only once
// a second for the keep-alive. Everything it hears is posted to the
// MqttClient on the event loop's thread (mqttclient.h).
//
// After a failure or a loss it connects again after 1, 2, 5, 10, then 30 s.
// Publish, subscribe and disconnect are called from the event loop's
// thread; libmosquitto, told it is threaded, queues them and wakes the loop.
// Internal to MqttClient.

#include "mqttsettings.h"

#include <QByteArray>
#include <QList>
#include <QString>

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>

struct mosquitto;
struct mosquitto_message;
typedef struct mqtt5__property mosquitto_property;

namespace slew::remote {

class MqttClient;

class MosquittoThread : public std::enable_shared_from_this<MosquittoThread> {
public:
    // Makes the connection and starts its thread; events go to `receiver`
    // until abandon(). Null, with *error, if libmosquitto refuses the
    // settings (a certificate file it cannot use, say).
    static std::shared_ptr<MosquittoThread> start(const MqttSettings &settings, MqttClient *receiver,
                                                  QString *error);
    ~MosquittoThread();

    // From the receiver's thread. libmosquitto's MOSQ_ERR_* codes.
    int publish(const MqttMessage &message, int *mid);
    int subscribe(const QString &filter, int qos, int *mid);
    // Publishes `last` (when given) and, once the broker has taken it,
    // disconnects cleanly, so the broker keeps the will to itself; the
    // thread ends once both have left.
    void close(const std::optional<MqttMessage> &last);
    // The receiver is going: nothing more is posted to it, the connection
    // is closed, and the thread is waited for up to `waitMs` (a thread stuck
    // in a name lookup is left to end by itself).
    void abandon(int waitMs);
    // A received message was taken off the queue (the flood guard's count).
    void messageTaken() { --m_waiting; }

private:
    explicit MosquittoThread(const MqttSettings &settings);
    bool configure(QString *error);
    void run();
    // One connection: made, then served until it ends or fails (the
    // MOSQ_ERR_* code; *wasUp once the broker accepted it). `bindAddress`
    // picks the address family (run()).
    int connectOnce(const QByteArray &host, const char *bindAddress, bool *wasUp);
    // The clean end of a connection, on the thread itself (close()).
    void disconnectNow();
    bool waitBeforeRetry(int seconds);
    bool stopping();
    // Runs `call` on the receiver's thread, unless it has gone.
    template <typename Call>
    void post(Call call);

    static void onConnect(mosquitto *, void *self, int reason, int flags, const mosquitto_property *);
    static void onDisconnect(mosquitto *, void *self, int reason, const mosquitto_property *);
    static void onPublish(mosquitto *, void *self, int mid, int reason, const mosquitto_property *);
    static void onSubscribe(mosquitto *, void *self, int mid, int count, const int *granted, const mosquitto_property *);
    static void onMessage(mosquitto *, void *self, const mosquitto_message *message, const mosquitto_property *);

    MqttSettings m_settings;
    mosquitto *m_mosq = nullptr;
    std::thread m_thread;
    std::mutex m_mutex; // guards the receiver, the flags and the wait
    std::condition_variable m_wake;
    MqttClient *m_receiver = nullptr;
    bool m_stopping = false;
    bool m_closing = false;
    // The last message's id: its acknowledgement ends the connection
    // (onPublish). -1 while none is awaited. Guarded by m_mutex.
    int m_lastMid = -1;
    bool m_finished = false; // run() has returned
    // Set by the callbacks, which run on the thread itself.
    std::atomic<bool> m_connected{false};
    // close() wants the connection ended; the thread does it (disconnectNow).
    std::atomic<bool> m_disconnectDue{false};
    QString m_refusal; // the broker's answer to a refused connection
    int m_failureErrno = 0; // errno when connectOnce's last call failed
    std::atomic<int> m_waiting{0};
    std::atomic<int> m_dropped{0};
    std::atomic<int> m_oversized{0};
};

} // namespace slew::remote
