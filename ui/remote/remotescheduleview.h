// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Schedule tab of a remote station's window: the schedule the station
// published (remote/stationschedule.h) on the same time line as the local
// Schedule page (scheduletimeline.h), a line of its figures above it and,
// below, the pass being followed. It only shows: a schedule is made at the
// station (its service's --track list, or its own window).

#include <QWidget>

class QLabel;

namespace slew::face {
struct StationSchedule;
}

namespace slew::ui {

class ScheduleTimeline;

class RemoteScheduleView : public QWidget {
    Q_OBJECT
public:
    explicit RemoteScheduleView(QWidget *parent = nullptr);

    void showSchedule(const face::StationSchedule &schedule, qint64 receivedUnixMs);
    // Moves the time line's "now" on by the wall clock since the schedule
    // came, at the station clock's rate (a rehearsal runs faster).
    void showTime(qint64 unixMs);

    ScheduleTimeline *timeline() const { return m_timeline; }
    QString summary() const;
    QString currentText() const;

private:
    QLabel *m_summary;
    QLabel *m_current;
    ScheduleTimeline *m_timeline;
    qint64 m_clockMs = 0, m_receivedMs = 0;
    double m_rate = 1;
    bool m_running = false;
};

} // namespace slew::ui
