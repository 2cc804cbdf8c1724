// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Previews a schedule as the Station would run it now: each target named
// in words found as a track command finds it (targetbyname.h), and the
// plan made on a worker thread from the station's clock, place, horizon
// and rotator (scheduleSettingsNow, the run's own settings). It moves
// nothing. One preview is made at a time: a new one lets the one still
// being planned go, answered refused, so a face typing fast (or a broker's
// flood) never queues plans.
//
// Each face that previews has its own (the window's face, the broker's
// commands), so one does not let another's go.

#include "face/schedulepreview.h"
#include "face/schedulerequest.h"
#include "sky/elementset.h"

#include <QList>
#include <QObject>
#include <QStringList>

#include <atomic>
#include <memory>

namespace slew::station {

class Station;

class SchedulePreviewer : public QObject {
    Q_OBJECT
public:
    // `given`: the sets the station was started with, looked in first, as
    // its track command does. The station must outlive this.
    SchedulePreviewer(Station *station, const QList<sky::ElementSet> &given, QObject *parent = nullptr);
    ~SchedulePreviewer() override;

    // Answered later, by `previewed` or `refused` with this id.
    void preview(const QString &id, const QStringList &targets, const face::ScheduleRequest &request);

signals:
    void previewed(const QString &id, const slew::face::SchedulePreview &preview);
    void refused(const QString &id, const QString &why);

private:
    void letGo(const QString &why);

    Station *m_station;
    QList<sky::ElementSet> m_given;
    QString m_pendingId;
    std::shared_ptr<std::atomic<bool>> m_stop; // the plan being made gives up when set
    int m_generation = 0;
};

} // namespace slew::station
