// SPDX-License-Identifier: GPL-3.0-or-later
#include "remoteoperation.h"

#include "remotecommands.h"
#include "station.h"
#include "planpublisher.h"
#include "statepublisher.h"

#include "remote/mqttclient.h"
#include "remote/stationtopics.h"
#include "sky/elementsetsources.h"

#include <QUuid>

namespace slew::station {

using remote::MqttClient;
using remote::MqttMessage;
using remote::StationTopic;

namespace {

MqttMessage onlineMessage(const QString &name, bool online)
{
    return {remote::stationTopic(name, StationTopic::Online), online ? "true" : "false", 1, true};
}

} // namespace

RemoteOperation::RemoteOperation(Station *station, const RemoteOptions &options, QObject *parent)
    : QObject(parent), m_station(station), m_options(options)
{
    remote::MqttSettings settings;
    settings.broker = options.broker;
    settings.password = options.password;
    // One connection per station name: a second instance of the same
    // station takes over, and the broker closes the first.
    settings.clientId = QStringLiteral("slew-station-%1").arg(options.stationName);
    settings.will = onlineMessage(options.stationName, false);
    m_client = std::make_unique<MqttClient>(settings);
    m_publisher = std::make_unique<StatePublisher>(
        station, options.stationName, [this](const MqttMessage &m) { publish(m); });
    m_plans = std::make_unique<PlanPublisher>(station, options.stationName,
                                              [this](const MqttMessage &m) { publish(m); });
    m_commands = std::make_unique<RemoteCommands>(station, options.elementSets);
    m_commandTopic = remote::stationTopic(options.stationName, StationTopic::Command);
    connect(m_commands.get(), &RemoteCommands::logLine, this, &RemoteOperation::logLine);
    connect(m_commands.get(), &RemoteCommands::lateReply, this, [this](const remote::RemoteReply &reply) {
        publish({remote::stationTopic(m_options.stationName, StationTopic::Reply), remote::encodeRemoteReply(reply), 1,
                 false});
    });
    connect(m_client.get(), &MqttClient::connected, this, &RemoteOperation::onConnected);
    connect(m_client.get(), &MqttClient::connectionLost, this, [this](const QString &why, int retry) {
        m_publisher->setEnabled(false);
        m_plans->setEnabled(false);
        emit logLine(tr("remote: %1: %2; trying again in %3 s").arg(m_client->settings().broker.display(), why).arg(retry));
    });
    connect(m_client.get(), &MqttClient::messageReceived, this,
            [this](const QString &topic, const QByteArray &payload) { onMessage(topic, payload); });
    connect(m_client.get(), &MqttClient::messagesDropped, this, [this](int count, const QString &why) {
        emit logLine(tr("remote: %1 messages from the broker dropped unread: %2").arg(count).arg(why));
    });
    connect(m_client.get(), &MqttClient::subscriptionRefused, this, [this](const QString &filter, const QString &why) {
        emit logLine(tr("remote: the broker refused to let this station read %1 (%2): check its access list")
                         .arg(filter, why));
    });
    connect(m_client.get(), &MqttClient::publishRefused, this, [this](int, const QString &why) {
        emit logLine(tr("remote: the broker refused a message from this station (%1): check its access list").arg(why));
    });
    connect(m_client.get(), &MqttClient::closed, this, &RemoteOperation::closed);
}

RemoteOperation::~RemoteOperation() = default;

bool RemoteOperation::start(QString *error)
{
    // A remote `track` may name any satellite the station has cached.
    sky::ElementSetSources *sets = m_station->elementSets();
    if (sets->sets().isEmpty()) {
        sets->setUrls(sky::savedElementSetUrls());
        sets->loadFromCache();
    }
    m_client->subscribe(m_commandTopic, 1);
    return m_client->open(error);
}

void RemoteOperation::publish(const MqttMessage &message)
{
    m_client->publish(message);
}

void RemoteOperation::onConnected()
{
    emit logLine(tr("remote: connected to %1: publishing slew/%2/").arg(m_client->settings().broker.display(),
                                                                       m_options.stationName));
    publish(onlineMessage(m_options.stationName, true));
    m_publisher->setEnabled(true);
    m_publisher->publishState();
    m_plans->setEnabled(true);
    m_plans->publishNow();
}

void RemoteOperation::onMessage(const QString &topic, const QByteArray &payload)
{
    if (topic != m_commandTopic)
        return;
    const std::optional<remote::RemoteReply> reply = m_commands->handle(payload);
    if (reply)
        publish({remote::stationTopic(m_options.stationName, StationTopic::Reply), remote::encodeRemoteReply(*reply), 1,
                 false});
}

void RemoteOperation::close(const QString &why)
{
    if (m_closing)
        return;
    m_closing = true;
    m_commands->refuseFromNow(tr("the station is shutting down (%1)").arg(why));
    if (m_client->isConnected())
        m_publisher->publishState();
    m_publisher->setEnabled(false);
    m_plans->setEnabled(false);
    m_client->close(onlineMessage(m_options.stationName, false));
}

} // namespace slew::station
