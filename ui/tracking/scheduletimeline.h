// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A schedule on a time line (schedule/schedule.h): a lane a target, in
// priority order, across the planned hours; each taken pass a solid bar,
// each dropped one a hollow, hatched bar whose tooltip says why; the pass
// being followed outlined bright, and a line at the station clock's now.

#include "schedule/schedule.h"

#include <QWidget>

#include <optional>

namespace slew::ui {

class ScheduleTimeline : public QWidget {
    Q_OBJECT
public:
    explicit ScheduleTimeline(QWidget *parent = nullptr);

    void setSchedule(const schedule::Schedule &schedule);
    // The pass followed now (its target and start); none: none is.
    void setCurrent(const std::optional<schedule::ScheduledPass> &pass);
    void setNow(double julian);

    // Where a pass's bar is drawn, for tests; empty when it is not shown.
    QRectF barFor(const schedule::ScheduledPass &pass) const;
    const schedule::Schedule &schedule() const { return m_schedule; }
    // Where the time line starts: the plan's start, or now while there is no
    // plan; and the day over its names ("UTC, 5 Dec").
    double startJulian() const;
    QString dayText() const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent *event) override;
    bool event(QEvent *event) override; // tooltips

private:
    QRectF plotArea() const;
    double xFor(double julian) const;
    int laneCount() const;
    const schedule::ScheduledPass *passAt(const QPointF &pos) const;

    schedule::Schedule m_schedule;
    std::optional<schedule::ScheduledPass> m_current;
    double m_now = 0;
};

} // namespace slew::ui
