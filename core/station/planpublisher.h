// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a station says on the broker about what it means to do: the plan of
// the pass ahead (remote/stationplan.h) and its schedule
// (remote/stationschedule.h), both retained, so a window that opens later
// sees them at once. Each goes out when it changes, changes that come
// together as one message, and never again while it stays the same: a
// station at rest publishes nothing here.

#include "remote/mqttsettings.h"

#include <QByteArray>
#include <QObject>
#include <QTimer>

#include <functional>

namespace slew::station {

class Station;

class PlanPublisher : public QObject {
    Q_OBJECT
public:
    static constexpr int kGatherMs = 200;

    using Publish = std::function<void(const remote::MqttMessage &)>;
    PlanPublisher(Station *station, const QString &stationName, Publish publish, QObject *parent = nullptr);

    // On a new connection: both again (the broker keeps them, but it may be
    // another broker, or it may have been restarted without its store).
    void publishNow();
    void setEnabled(bool on);

    QByteArray planMessage() const;
    QByteArray scheduleMessage() const;
    int plansPublished() const { return m_plans; }
    int schedulesPublished() const { return m_schedules; }

private:
    void changed();
    void publishChanged(bool always);

    Station *m_station;
    QString m_name;
    Publish m_publish;
    bool m_enabled = false;
    QTimer m_due;
    QByteArray m_lastPlan, m_lastSchedule; // as sent, without the time stamp
    int m_plans = 0, m_schedules = 0;
};

} // namespace slew::station
