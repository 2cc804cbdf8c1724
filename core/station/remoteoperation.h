// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Station on an MQTT broker: remote operation, a part of the Station
// that every face gets by asking (Station::startRemote). Under
// `slew/NAME/` (remote/stationtopics.h) it publishes the station's state
// and telemetry (statepublisher.h), says `online` true while connected
// (false as its will, and on a clean exit), and obeys `command` under the
// station's rules, answering each on `reply` (remotecommands.h).
//
// The broker is reached over TLS with the station's own account; its
// access list decides who may watch and who may command (docs/remote.md).
// A lost broker is tried again with a growing wait; the rotator is never
// waited on it.

#include "remote/brokeraddress.h"
#include "sky/elementsetformat.h"

#include <QObject>

#include <memory>

namespace slew::remote {
class MqttClient;
struct MqttMessage;
}

namespace slew::station {

class RemoteCommands;
class PlanPublisher;
class StatePublisher;
class Station;

struct RemoteOptions {
    remote::BrokerAddress broker;
    QString password;
    QString stationName;
    // Satellites a remote `track` may name besides the element-set cache's
    // (the service's --tle).
    QList<sky::ElementSet> elementSets;
};

class RemoteOperation : public QObject {
    Q_OBJECT
public:
    RemoteOperation(Station *station, const RemoteOptions &options, QObject *parent = nullptr);
    ~RemoteOperation() override;

    // Starts connecting; false, with *error, when the settings cannot be used.
    bool start(QString *error);
    // Obeys nothing more but stop, publishes the last state and
    // online = false, disconnects cleanly, then emits closed().
    void close(const QString &why);

    const RemoteOptions &options() const { return m_options; }
    remote::MqttClient *client() const { return m_client.get(); }
    StatePublisher *publisher() const { return m_publisher.get(); }
    PlanPublisher *planPublisher() const { return m_plans.get(); }
    RemoteCommands *commands() const { return m_commands.get(); }

signals:
    void logLine(const QString &line);
    void closed();

private:
    void onConnected();
    void onMessage(const QString &topic, const QByteArray &payload);
    void publish(const remote::MqttMessage &message);

    Station *m_station;
    RemoteOptions m_options;
    std::unique_ptr<remote::MqttClient> m_client;
    std::unique_ptr<StatePublisher> m_publisher;
    std::unique_ptr<PlanPublisher> m_plans;
    std::unique_ptr<RemoteCommands> m_commands;
    QString m_commandTopic;
    bool m_closing = false;
};

} // namespace slew::station
