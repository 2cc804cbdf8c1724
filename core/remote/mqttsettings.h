// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What one MQTT connection is made with: the broker, the account, the last
// will, and how long to wait. Plain values.

#include "brokeraddress.h"

#include <QByteArray>
#include <QString>

#include <optional>

namespace slew::remote {

// A message the broker publishes for us when we vanish without a word (the
// process killed, the network cut), and one we publish ourselves on a
// clean exit: a station's `online = false`.
struct MqttMessage {
    QString topic;
    QByteArray payload;
    int qos = 1;
    bool retain = false;
};

struct MqttSettings {
    BrokerAddress broker;
    QString password;
    QString clientId;                  // empty: the library makes one up
    std::optional<MqttMessage> will;
    // The broker notices a silent client after 1.5 times this, and sends its will.
    int keepAliveSeconds = 10;
    // A broker that has not answered the connection (TCP, TLS, CONNACK) by
    // then is given up on, and tried again after the backoff.
    int connectTimeoutMs = 10000;
    // Messages larger than this are dropped unread (a station's state is a
    // kilobyte or two; a command, under a hundred bytes).
    int largestMessage = 64 * 1024;
    // Received messages waiting for the event loop, beyond which more are
    // counted and dropped: a flood from the broker cannot fill the memory.
    int mostWaiting = 2000;
};

// Seconds to wait before each new attempt after a failure or a loss: 1, 2,
// 5, 10, then every 30 s.
int reconnectDelaySeconds(int attempt);

} // namespace slew::remote
