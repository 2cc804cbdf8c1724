// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The stations a broker knows: every `slew/+/online` and `slew/+/state`
// it passes on (both retained, so a directory opened now hears of every
// station at once), each checked as a RemoteStation checks them. What the
// station network window shows, one small plot per station.

#include "mqttclient.h"
#include "stationstate.h"

#include "input/logtext.h"

#include <QElapsedTimer>
#include <QMap>
#include <QObject>

#include <optional>

namespace slew::remote {

class StationDirectory : public QObject {
    Q_OBJECT
public:
    // A broker that names more stations than this is not believed further.
    static constexpr int kMostStations = 500;

    struct Entry {
        bool online = false;
        std::optional<face::StationState> state;
        QElapsedTimer sinceState; // invalid before the first
    };

    explicit StationDirectory(const MqttSettings &settings, QObject *parent = nullptr);
    ~StationDirectory() override;

    bool open(QString *error);
    MqttClient *client() const { return m_client.get(); }
    QString brokerDisplay() const { return m_client->settings().broker.display(); }

    QStringList names() const { return m_stations.keys(); }
    const Entry *station(const QString &name) const;
    // Online, with a state younger than RemoteStation::kStaleAfterMs.
    bool isLive(const QString &name) const;

signals:
    void stationAdded(const QString &name);
    void stationChanged(const QString &name);
    void messageRefused(const QString &what);
    void connectionChanged(slew::remote::MqttClient::State state, const QString &detail);

private:
    void onMessage(const QString &topic, const QByteArray &payload);
    Entry *entry(const QString &name);

    std::unique_ptr<MqttClient> m_client;
    QMap<QString, Entry> m_stations; // by name, in order
    input::LogAllowance m_refusals{5, 0.1};
};

} // namespace slew::remote
