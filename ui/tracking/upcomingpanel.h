// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Tracking → Upcoming: the next passes of the operator's favourites (the
// satellites, sun and moon starred in One target), soonest first, with a
// countdown, the highest elevation and whether this rotator can make each
// one (the plan it would get, or why not). Planned off the window's
// thread, in the station's time; a double click opens the pass's target
// in One target.

#include "tracking/passforecast.h"

#include <QTimer>
#include <QWidget>

class QLabel;
class QTableWidget;

namespace slew::station {
class Station;
}

namespace slew::ui {

class UpcomingPanel : public QWidget {
    Q_OBJECT
public:
    explicit UpcomingPanel(station::Station *station, QWidget *parent = nullptr);

    struct Row {
        QString target; // as the station names it: "FLOCK 2P-1", "the sun"
        QString search; // what finds it in One target: its catalogue number, "sun", "moon"
        tracking::PlannedPass planned;
    };
    const QList<Row> &rows() const { return m_rows; }
    QTableWidget *table() const { return m_table; }
    bool isPlanning() const { return m_planning; }

public slots:
    // The favourites, the sets, the station, the clock or the rotator
    // changed: plan again.
    void refresh();

signals:
    void rowsShown();
    // A row was double-clicked: show this target in One target (`search`
    // as Row::search).
    void targetChosen(const QString &search);

private:
    void fill(const QList<Row> &rows);
    void tick(); // the countdowns; plans again once the first pass is over

    station::Station *m_station;
    QLabel *m_status;
    QTableWidget *m_table;
    QList<Row> m_rows;
    QTimer m_tick;
    int m_generation = 0; // a plan still being made for an older question is dropped
    bool m_planning = false;
};

} // namespace slew::ui
