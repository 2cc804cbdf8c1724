// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One station in the station network window: its name, its antenna on a
// small polar plot, a line of what it does (moving, tracking, the rotator's
// link) and how old that is, its alarms, and a button that opens it in a
// window of its own. Greyed while it is offline or silent.

#include "remote/stationstate.h"

#include <QFrame>

class QLabel;
class QPushButton;

namespace slew::ui {

class PolarPlotWidget;

class StationTile : public QFrame {
    Q_OBJECT
public:
    // Every tile the same size, so a network of twenty fits a 1440×900
    // window: seven a row, three rows.
    static constexpr int kWidth = 188;
    static constexpr int kHeight = 262;

    explicit StationTile(const QString &name, QWidget *parent = nullptr);

    QString name() const { return m_name; }
    PolarPlotWidget *plot() const { return m_plot; }
    QString statusText() const;

public slots:
    // `state` may be none (only `online` heard so far); ageMs since it came.
    void show(bool live, bool online, const std::optional<slew::face::StationState> &state, qint64 ageMs);

signals:
    void openRequested(const QString &name);

private:
    QString m_name;
    QLabel *m_title;
    PolarPlotWidget *m_plot;
    QLabel *m_status;
    QLabel *m_alarms;
    QPushButton *m_open;
    qint64 m_shownMs = -1; // the state on the plot
    bool m_shownStale = true;
};

} // namespace slew::ui
