// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a remote station's state says, for people: where the antenna points
// (large figures) and where it is going, whether it moves, the rotator's
// link and controller, the operator's hold, and its tracking with the pass.
// Greyed while the station is not live. Plain text throughout: every word
// came from the broker.

#include "remote/stationstate.h"

#include <QWidget>

class QLabel;

namespace slew::ui {

class RemoteReadout : public QWidget {
    Q_OBJECT
public:
    explicit RemoteReadout(QWidget *parent = nullptr);

    // "Pass of ISS (ZARYA) (NORAD 25544): 12:03:10–12:13:40 UTC, highest
    // 56.1°"; empty when no pass is followed or waited for.
    static QString trackingText(const face::StationState &state);

public slots:
    void showState(const slew::face::StationState &state);
    // Where the antenna points now, from the telemetry (between states).
    void showPosition(double az, double el);
    void setLive(bool live);

private:
    QLabel *m_az;
    QLabel *m_el;
    QLabel *m_target;
    QLabel *m_link;
    QLabel *m_tracking;
    bool m_azimuthOnly = false;
};

} // namespace slew::ui
