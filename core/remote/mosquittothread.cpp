// SPDX-License-Identifier: GPL-3.0-or-later
#include "mosquittothread.h"

#include "mqttclient.h"

#include <QMetaObject>

#include <mosquitto.h>
#include <mqtt_protocol.h>

#include <netdb.h>
#include <pthread.h>
#include <signal.h>
#include <sys/socket.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <mutex>
#include <vector>

namespace slew::remote {
namespace {

// How long one turn of the loop waits for the socket: also how soon a
// close() with no last message is acted on.
constexpr int kLoopWaitMs = 200;

// libmosquitto sets up a part of its TLS state (the method that would ask
// for a key's password) the first time a client connects, and not
// thread-safely: two clients of one process connecting at once (a station
// publishing itself and a window on another station) each make one, and
// one is lost. Their connects start one at a time; this is only the
// asynchronous start (and a name lookup), not the handshake.
std::timed_mutex &connectTurn()
{
    static std::timed_mutex turn;
    return turn;
}

void initialiseLibraryOnce()
{
    // Never cleaned up: a thread stuck in a name lookup may still use it as
    // the process ends.
    static std::once_flag once;
    std::call_once(once, [] { mosquitto_lib_init(); });
}

// The wildcard address of each family `host` resolves to, in the
// resolver's order ("::" for IPv6, "0.0.0.0" for IPv4), or one null (no
// binding) when it resolves to one family or not at all. Why: an
// asynchronous connect in libmosquitto takes the first address whose
// connect() is under way and never tries the next, so where "localhost" is
// ::1 first (Debian's /etc/hosts) and the broker listens on 127.0.0.1
// alone, the connection was refused and reported as "Protocol error" (the
// TLS handshake on a dead socket). Bound to a family's wildcard address,
// libmosquitto skips the addresses of the other family.
std::vector<const char *> wildcardAddressesFor(const QByteArray &host)
{
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    addrinfo *found = nullptr;
    std::vector<const char *> binds;
    if (getaddrinfo(host.constData(), nullptr, &hints, &found) == 0) {
        for (const addrinfo *a = found; a; a = a->ai_next) {
            const char *wildcard = a->ai_family == AF_INET6 ? "::" : a->ai_family == AF_INET ? "0.0.0.0" : nullptr;
            if (wildcard && std::find(binds.begin(), binds.end(), wildcard) == binds.end())
                binds.push_back(wildcard);
        }
        freeaddrinfo(found);
    }
    if (binds.size() < 2)
        return {nullptr};
    return binds;
}

const QString kTlsHandshakeFailed = QStringLiteral(
    "the TLS handshake failed (is the broker's certificate signed by the cafile's authority, and issued for this "
    "host name?)");

// What went wrong, for a person. `savedErrno` is errno as it was when the
// call failed (by now other calls may have changed it).
QString errorText(int rc, int savedErrno = errno)
{
    if (rc == MOSQ_ERR_ERRNO)
        return QString::fromLocal8Bit(std::strerror(savedErrno));
    if (rc == MOSQ_ERR_TLS)
        return kTlsHandshakeFailed;
    return QString::fromUtf8(mosquitto_strerror(rc));
}

// Why a connection that never came up failed. libmosquitto reports an
// OpenSSL error met while reading or writing as a system error with errno
// EPROTO ("Protocol error"): on a TLS connection that is the handshake
// failing, the same as MOSQ_ERR_TLS, which it reports when the failure
// comes a moment earlier (Debian 13's libmosquitto was seen to give either).
QString connectFailureText(int rc, int savedErrno, bool tls)
{
    if (tls && rc == MOSQ_ERR_ERRNO && savedErrno == EPROTO)
        return kTlsHandshakeFailed;
    return errorText(rc, savedErrno);
}

} // namespace

int reconnectDelaySeconds(int attempt)
{
    static constexpr int kDelays[] = {1, 2, 5, 10, 30};
    constexpr int count = int(std::size(kDelays));
    return kDelays[attempt < 0 ? 0 : (attempt < count ? attempt : count - 1)];
}

MosquittoThread::MosquittoThread(const MqttSettings &settings) : m_settings(settings) {}

MosquittoThread::~MosquittoThread()
{
    if (m_thread.joinable()) {
        if (m_thread.get_id() == std::this_thread::get_id())
            m_thread.detach(); // the thread's own last reference, as it ends
        else
            m_thread.join();
    }
    if (m_mosq)
        mosquitto_destroy(m_mosq);
}

std::shared_ptr<MosquittoThread> MosquittoThread::start(const MqttSettings &settings, MqttClient *receiver,
                                                        QString *error)
{
    initialiseLibraryOnce();
    std::shared_ptr<MosquittoThread> self(new MosquittoThread(settings));
    if (!self->configure(error))
        return nullptr;
    self->m_receiver = receiver;
    // The thread holds the object until it ends, however long the owner lives.
    self->m_thread = std::thread([keep = self] { keep->run(); });
    return self;
}

bool MosquittoThread::configure(QString *error)
{
    const QByteArray id = m_settings.clientId.toUtf8();
    m_mosq = mosquitto_new(id.isEmpty() ? nullptr : id.constData(), true, this);
    if (!m_mosq) {
        *error = QStringLiteral("libmosquitto could not make a client: %1").arg(errorText(MOSQ_ERR_ERRNO));
        return false;
    }
    mosquitto_threaded_set(m_mosq, true);
    mosquitto_int_option(m_mosq, MOSQ_OPT_PROTOCOL_VERSION, MQTT_PROTOCOL_V5);
    const BrokerAddress &b = m_settings.broker;
    int rc = MOSQ_ERR_SUCCESS;
    if (!b.user.isEmpty() || !m_settings.password.isEmpty()) {
        const QByteArray user = b.user.toUtf8(), password = m_settings.password.toUtf8();
        rc = mosquitto_username_pw_set(m_mosq, user.isEmpty() ? nullptr : user.constData(),
                                       password.isEmpty() ? nullptr : password.constData());
        if (rc != MOSQ_ERR_SUCCESS) {
            *error = QStringLiteral("the user name or password cannot be used: %1").arg(errorText(rc));
            return false;
        }
    }
    if (b.tls) {
        const QByteArray caFile = b.caFile.toLocal8Bit();
        // No cafile: the system's authorities, as a web browser trusts.
        rc = caFile.isEmpty() ? mosquitto_tls_set(m_mosq, nullptr, "/etc/ssl/certs", nullptr, nullptr, nullptr)
                              : mosquitto_tls_set(m_mosq, caFile.constData(), nullptr, nullptr, nullptr, nullptr);
        if (rc != MOSQ_ERR_SUCCESS) {
            *error = b.caFile.isEmpty()
                         ? QStringLiteral("the system's certificate authorities cannot be used: %1").arg(errorText(rc))
                         : QStringLiteral("cafile %1 cannot be used: %2").arg(b.caFile, errorText(rc));
            return false;
        }
        // The certificate must be signed by the authority and name the host.
        mosquitto_tls_opts_set(m_mosq, 1, nullptr, nullptr);
        mosquitto_tls_insecure_set(m_mosq, false);
    }
    if (m_settings.will) {
        const MqttMessage &w = *m_settings.will;
        const QByteArray topic = w.topic.toUtf8();
        rc = mosquitto_will_set(m_mosq, topic.constData(), int(w.payload.size()), w.payload.constData(), w.qos, w.retain);
        if (rc != MOSQ_ERR_SUCCESS) {
            *error = QStringLiteral("the last will on %1 cannot be set: %2").arg(w.topic, errorText(rc));
            return false;
        }
    }
    mosquitto_connect_v5_callback_set(m_mosq, &MosquittoThread::onConnect);
    mosquitto_disconnect_v5_callback_set(m_mosq, &MosquittoThread::onDisconnect);
    mosquitto_publish_v5_callback_set(m_mosq, &MosquittoThread::onPublish);
    mosquitto_subscribe_v5_callback_set(m_mosq, &MosquittoThread::onSubscribe);
    mosquitto_message_v5_callback_set(m_mosq, &MosquittoThread::onMessage);
    return true;
}

template <typename Call>
void MosquittoThread::post(Call call)
{
    std::lock_guard lock(m_mutex);
    if (m_receiver)
        QMetaObject::invokeMethod(m_receiver, [r = m_receiver, call = std::move(call)] { call(r); },
                                  Qt::QueuedConnection);
}

bool MosquittoThread::stopping()
{
    std::lock_guard lock(m_mutex);
    return m_stopping;
}

bool MosquittoThread::waitBeforeRetry(int seconds)
{
    std::unique_lock lock(m_mutex);
    return !m_wake.wait_for(lock, std::chrono::seconds(seconds), [this] { return m_stopping; });
}

void MosquittoThread::run()
{
    // A broker that goes away under TLS: OpenSSL writes with write(), not
    // send() with MSG_NOSIGNAL as libmosquitto does on plain TCP, and the
    // kernel answers a write to a closed connection with SIGPIPE, whose
    // default action ends the whole program (seen on Debian 13 when the
    // broker was stopped). Blocked in this thread, where libmosquitto does
    // all its writing (threaded mode), the write fails with EPIPE instead
    // and the loop reports a lost connection. Other threads are untouched.
    sigset_t brokenPipe;
    sigemptyset(&brokenPipe);
    sigaddset(&brokenPipe, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &brokenPipe, nullptr);

    const QByteArray host = m_settings.broker.host.toUtf8();
    int attempt = 0;
    std::size_t familyThatWorked = 0;
    while (!stopping()) {
        // One try for each address family the name resolves to, starting
        // with the one that worked last time; see wildcardAddressesFor.
        const std::vector<const char *> binds = wildcardAddressesFor(host);
        QString why;
        bool wasUp = false;
        for (std::size_t tried = 0; tried < binds.size() && !stopping(); ++tried) {
            const std::size_t family = (familyThatWorked + tried) % binds.size();
            const int rc = connectOnce(host, binds[family], &wasUp);
            if (stopping())
                break;
            const QString reason = !m_refusal.isEmpty()     ? m_refusal
                                   : rc == MOSQ_ERR_TIMEOUT ? QStringLiteral("no answer within %1 s").arg(m_settings.connectTimeoutMs / 1000)
                                   : rc == MOSQ_ERR_CONN_LOST ? QStringLiteral("the connection was lost")
                                   : wasUp ? errorText(rc, m_failureErrno)
                                           : connectFailureText(rc, m_failureErrno, m_settings.broker.tls);
            // The reason from the family that got furthest: a socket error
            // (nobody listening there) says less than a broker's answer.
            const bool socketError = rc == MOSQ_ERR_ERRNO && !(m_settings.broker.tls && m_failureErrno == EPROTO);
            if (why.isEmpty() || !socketError)
                why = reason;
            if (wasUp || !m_refusal.isEmpty()) {
                if (wasUp) {
                    familyThatWorked = family;
                    attempt = 0;
                }
                break;
            }
        }
        if (stopping())
            break;
        const int delay = reconnectDelaySeconds(attempt++);
        post([why, delay](MqttClient *c) { c->onLost(why, delay); });
        if (!waitBeforeRetry(delay))
            break;
    }
    post([](MqttClient *c) { c->onFinished(); });
    std::lock_guard lock(m_mutex);
    m_finished = true;
    m_wake.notify_all();
}

int MosquittoThread::connectOnce(const QByteArray &host, const char *bindAddress, bool *wasUp)
{
    m_connected = false;
    m_refusal.clear();
    // Asynchronous: the TCP connect and the TLS handshake go on in the
    // loop below, which can give up on them; only a name lookup waits here.
    m_failureErrno = 0;
    std::unique_lock turn(connectTurn(), std::defer_lock);
    while (!turn.try_lock_for(std::chrono::milliseconds(kLoopWaitMs))) {
        if (stopping())
            return MOSQ_ERR_CONN_LOST; // the caller sees it is stopping
    }
    int rc = mosquitto_connect_bind_async(m_mosq, host.constData(), m_settings.broker.port,
                                          m_settings.keepAliveSeconds, bindAddress);
    turn.unlock();
    if (rc != MOSQ_ERR_SUCCESS) {
        m_failureErrno = errno;
        return rc;
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(m_settings.connectTimeoutMs);
    while (!stopping()) {
        // A short wait, so that a close() with nothing to wait for is
        // acted on soon: only this thread may disconnect (close()).
        rc = mosquitto_loop(m_mosq, kLoopWaitMs, 1);
        if (rc != MOSQ_ERR_SUCCESS) {
            m_failureErrno = errno;
            return rc;
        }
        if (m_disconnectDue.exchange(false))
            disconnectNow();
        if (m_connected)
            *wasUp = true;
        else if (!*wasUp && std::chrono::steady_clock::now() > deadline)
            return MOSQ_ERR_TIMEOUT;
    }
    return MOSQ_ERR_SUCCESS;
}

int MosquittoThread::publish(const MqttMessage &message, int *mid)
{
    const QByteArray topic = message.topic.toUtf8();
    return mosquitto_publish(m_mosq, mid, topic.constData(), int(message.payload.size()), message.payload.constData(),
                             message.qos, message.retain);
}

int MosquittoThread::subscribe(const QString &filter, int qos, int *mid)
{
    return mosquitto_subscribe(m_mosq, mid, filter.toUtf8().constData(), qos);
}

void MosquittoThread::close(const std::optional<MqttMessage> &last)
{
    const bool connected = m_connected;
    std::lock_guard lock(m_mutex);
    m_closing = true;
    // Not connected (still connecting, or waiting to try again): there
    // is nobody to say goodbye to, and the thread ends at once.
    if (!connected) {
        m_stopping = true;
        m_wake.notify_all();
        return;
    }
    // The disconnect is left to the thread, after the broker has taken the
    // last message. Sent from here, it marks the connection closing at once,
    // and libmosquitto then refuses whatever arrives before its own loop has
    // written the queue (a command for the station, an acknowledgement) by
    // dropping the connection: the last message and the goodbye were lost
    // and the broker published the will (seen under load). The mutex keeps
    // onPublish from looking for the id before it is known.
    int mid = -1;
    if (last && publish(*last, &mid) == MOSQ_ERR_SUCCESS)
        m_lastMid = mid;
    else
        m_disconnectDue = true;
}

void MosquittoThread::disconnectNow()
{
    // Queued behind everything not yet written; written here and now, so
    // that nothing is read in between. Once the goodbye is out the library
    // closes the socket and onDisconnect ends the thread.
    if (mosquitto_disconnect(m_mosq) == MOSQ_ERR_NO_CONN) {
        std::lock_guard lock(m_mutex);
        m_stopping = true;
        m_wake.notify_all();
        return;
    }
    mosquitto_loop_write(m_mosq, 1);
}

void MosquittoThread::abandon(int waitMs)
{
    {
        std::lock_guard lock(m_mutex);
        m_receiver = nullptr;
        m_stopping = true;
        m_wake.notify_all();
    }
    mosquitto_disconnect(m_mosq); // wakes the loop's select()
    if (!m_thread.joinable())
        return;
    // The thread ends within a turn of its loop, unless a name lookup holds
    // it; then it is left to end by itself, holding its own reference.
    std::unique_lock lock(m_mutex);
    const bool ended = m_wake.wait_for(lock, std::chrono::milliseconds(waitMs), [this] { return m_finished; });
    lock.unlock();
    if (ended)
        m_thread.join();
    else
        m_thread.detach();
}

void MosquittoThread::onConnect(mosquitto *, void *self, int reason, int, const mosquitto_property *)
{
    auto *t = static_cast<MosquittoThread *>(self);
    if (reason == 0) {
        t->m_connected = true;
        t->post([](MqttClient *c) { c->onConnected(); });
        return;
    }
    t->m_refusal = QStringLiteral("the broker refused the connection: %1").arg(QString::fromUtf8(mosquitto_reason_string(reason)));
}

void MosquittoThread::onDisconnect(mosquitto *, void *self, int, const mosquitto_property *)
{
    auto *t = static_cast<MosquittoThread *>(self);
    t->m_connected = false;
    std::lock_guard lock(t->m_mutex);
    if (t->m_closing) {
        t->m_stopping = true;
        t->m_wake.notify_all();
    }
}

void MosquittoThread::onPublish(mosquitto *, void *self, int mid, int reason, const mosquitto_property *)
{
    auto *t = static_cast<MosquittoThread *>(self);
    {
        std::lock_guard lock(t->m_mutex);
        if (t->m_closing && mid == t->m_lastMid) {
            t->m_lastMid = -1;
            t->m_disconnectDue = true; // acted on as soon as this callback returns
        }
    }
    // Only a refusal is news (MQTT 5: a PUBACK reason of 0x80 or more, the
    // access list's "not authorised"). Every message taken would otherwise
    // wake the event loop once more for nothing: a station publishes ten a
    // second while it slews.
    if (reason >= 0x80)
        t->post([mid, reason](MqttClient *c) { c->onRefused(mid, reason); });
}

void MosquittoThread::onSubscribe(mosquitto *, void *self, int mid, int count, const int *granted,
                                  const mosquitto_property *)
{
    QList<int> codes;
    for (int i = 0; i < count; ++i)
        codes.append(granted[i]);
    static_cast<MosquittoThread *>(self)->post([mid, codes](MqttClient *c) { c->onSubscribed(mid, codes); });
}

void MosquittoThread::onMessage(mosquitto *, void *self, const mosquitto_message *message, const mosquitto_property *)
{
    auto *t = static_cast<MosquittoThread *>(self);
    if (message->payloadlen > t->m_settings.largestMessage) {
        if (t->m_oversized++ == 0)
            t->post([t](MqttClient *c) {
                c->onDropped(t->m_oversized.exchange(0),
                             QStringLiteral("larger than %1 bytes").arg(t->m_settings.largestMessage));
            });
        return;
    }
    if (t->m_waiting.load() >= t->m_settings.mostWaiting) {
        if (t->m_dropped++ == 0)
            t->post([t](MqttClient *c) {
                c->onDropped(t->m_dropped.exchange(0), QStringLiteral("arriving faster than they can be read"));
            });
        return;
    }
    ++t->m_waiting;
    const QString topic = QString::fromUtf8(message->topic);
    const QByteArray payload(static_cast<const char *>(message->payload), message->payloadlen);
    const bool retained = message->retain;
    t->post([t, topic, payload, retained](MqttClient *c) {
        t->messageTaken();
        c->onMessage(topic, payload, retained);
    });
}

} // namespace slew::remote
