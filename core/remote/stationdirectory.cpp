// SPDX-License-Identifier: GPL-3.0-or-later
#include "stationdirectory.h"

#include "remotestation.h"
#include "stationtopics.h"

#include <QDateTime>

namespace slew::remote {

StationDirectory::StationDirectory(const MqttSettings &settings, QObject *parent)
    : QObject(parent), m_client(std::make_unique<MqttClient>(settings))
{
    m_client->subscribe(everyStationFilter(StationTopic::Online), 1);
    m_client->subscribe(everyStationFilter(StationTopic::State), 1);
    connect(m_client.get(), &MqttClient::messageReceived, this,
            [this](const QString &topic, const QByteArray &payload) { onMessage(topic, payload); });
    connect(m_client.get(), &MqttClient::stateChanged, this, &StationDirectory::connectionChanged);
}

StationDirectory::~StationDirectory() = default;

bool StationDirectory::open(QString *error)
{
    return m_client->open(error);
}

const StationDirectory::Entry *StationDirectory::station(const QString &name) const
{
    const auto it = m_stations.constFind(name);
    return it == m_stations.cend() ? nullptr : &*it;
}

bool StationDirectory::isLive(const QString &name) const
{
    const Entry *e = station(name);
    return m_client->isConnected() && e && e->online && e->state && e->sinceState.isValid()
           && e->sinceState.elapsed() <= RemoteStation::kStaleAfterMs;
}

StationDirectory::Entry *StationDirectory::entry(const QString &name)
{
    auto it = m_stations.find(name);
    if (it != m_stations.end())
        return &*it;
    if (m_stations.size() >= kMostStations) {
        if (m_refusals.take(QDateTime::currentMSecsSinceEpoch()))
            emit messageRefused(tr("station %1 ignored: the broker names more than %2 stations").arg(name).arg(kMostStations));
        return nullptr;
    }
    it = m_stations.insert(name, Entry{});
    emit stationAdded(name);
    return &*it;
}

void StationDirectory::onMessage(const QString &topic, const QByteArray &payload)
{
    const std::optional<ParsedTopic> parsed = parseStationTopic(topic);
    if (!parsed)
        return;
    QString why;
    if (parsed->topic == StationTopic::Online) {
        if (payload != "true" && payload != "false") {
            if (m_refusals.take(QDateTime::currentMSecsSinceEpoch()))
                emit messageRefused(tr("%1: neither true nor false").arg(topic));
            return;
        }
        Entry *e = entry(parsed->stationName);
        if (!e)
            return;
        e->online = payload == "true";
        emit stationChanged(parsed->stationName);
    } else if (parsed->topic == StationTopic::State) {
        std::optional<face::StationState> state = parseStationState(payload, &why);
        if (!state) {
            if (m_refusals.take(QDateTime::currentMSecsSinceEpoch()))
                emit messageRefused(tr("%1 dropped: %2").arg(topic, why));
            return;
        }
        Entry *e = entry(parsed->stationName);
        if (!e)
            return;
        e->state = std::move(state);
        e->sinceState.start();
        emit stationChanged(parsed->stationName);
    }
}

} // namespace slew::remote
