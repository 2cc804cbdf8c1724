// SPDX-License-Identifier: GPL-3.0-or-later
#include "mqttclient.h"

#include "mosquittothread.h"

#include <mosquitto.h>

namespace slew::remote {

MqttClient::MqttClient(const MqttSettings &settings, QObject *parent) : QObject(parent), m_settings(settings)
{
    m_closeWait.setSingleShot(true);
    m_closeWait.setInterval(kCloseWaitMs);
    connect(&m_closeWait, &QTimer::timeout, this, &MqttClient::onFinished);
}

MqttClient::~MqttClient()
{
    if (m_thread)
        m_thread->abandon(500);
}

void MqttClient::setState(State state, const QString &detail)
{
    if (state == m_state && detail == m_problem)
        return;
    m_state = state;
    m_problem = state == State::Connected ? QString() : detail;
    emit stateChanged(state, detail);
}

bool MqttClient::open(QString *error)
{
    if (m_thread)
        return true;
    m_thread = MosquittoThread::start(m_settings, this, error);
    if (!m_thread)
        return false;
    setState(State::Connecting);
    return true;
}

bool MqttClient::publish(const MqttMessage &message, int *mid)
{
    if (m_state != State::Connected)
        return false;
    return m_thread->publish(message, mid) == MOSQ_ERR_SUCCESS;
}

void MqttClient::subscribe(const QString &filter, int qos)
{
    m_subscriptions.append({filter, qos});
    if (m_state == State::Connected) {
        int mid = 0;
        if (m_thread->subscribe(filter, qos, &mid) == MOSQ_ERR_SUCCESS)
            m_pendingSubscriptions.insert(mid, filter);
    }
}

void MqttClient::close(const std::optional<MqttMessage> &last)
{
    if (m_state == State::Closed || m_closeWait.isActive())
        return;
    if (!m_thread) {
        setState(State::Closed);
        emit closed();
        return;
    }
    m_thread->close(m_state == State::Connected ? last : std::nullopt);
    m_closeWait.start();
}

void MqttClient::onConnected()
{
    if (m_closeWait.isActive())
        return;
    m_pendingSubscriptions.clear();
    setState(State::Connected);
    // A clean session each time: the subscriptions are made again.
    for (const Subscription &s : std::as_const(m_subscriptions)) {
        int mid = 0;
        if (m_thread->subscribe(s.filter, s.qos, &mid) == MOSQ_ERR_SUCCESS)
            m_pendingSubscriptions.insert(mid, s.filter);
    }
    emit connected();
}

void MqttClient::onLost(const QString &why, int retryInSeconds)
{
    if (m_closeWait.isActive())
        return;
    setState(State::Reconnecting, why);
    emit connectionLost(why, retryInSeconds);
}

void MqttClient::onMessage(const QString &topic, const QByteArray &payload, bool retained)
{
    if (m_state == State::Closed)
        return;
    emit messageReceived(topic, payload, retained);
}

void MqttClient::onRefused(int mid, int reason)
{
    emit publishRefused(mid, QString::fromUtf8(mosquitto_reason_string(reason)));
}

void MqttClient::onSubscribed(int mid, const QList<int> &granted)
{
    const QString filter = m_pendingSubscriptions.take(mid);
    for (int code : granted) {
        if (code >= 0x80)
            emit subscriptionRefused(filter, QString::fromUtf8(mosquitto_reason_string(code)));
    }
}

void MqttClient::onDropped(int count, const QString &why)
{
    m_dropped += count;
    emit messagesDropped(count, why);
}

void MqttClient::onFinished()
{
    if (m_state == State::Closed)
        return;
    m_closeWait.stop();
    setState(State::Closed);
    emit closed();
}

} // namespace slew::remote
