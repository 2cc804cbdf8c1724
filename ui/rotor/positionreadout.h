// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where the rotator is, in large figures, with the target and what the
// controller says each axis is doing, read through the station's face
// (face/stationface.h), here or on a broker alike. Dimmed when the
// position is stale; greyed when what it shows is not live (a remote
// station's last word). For a station seen from afar it also says what the
// local window shows elsewhere: the rotator's link and controller, the
// hold of the operator at the station, and the pass being followed.

#include "face/stationstate.h"

#include <QWidget>

class QLabel;

namespace slew::face {
class StationFace;
struct TelemetrySample;
}

namespace slew::ui {

// A figure rounded to a tenth for display, never "-0.0".
double shownTenths(double value);

class PositionReadout : public QWidget {
    Q_OBJECT
public:
    explicit PositionReadout(face::StationFace *station, QWidget *parent = nullptr);

    // The pass a state says is followed, as a remote readout shows it:
    // "Pass of ISS (NORAD 25544): 10:02:11–10:12:40 UTC, highest 56.1°".
    static QString passText(const face::StationState &state);

private:
    void showState(const face::StationState &state);
    void showSample(const face::TelemetrySample &sample);
    void showPosition(double az, double el, bool stale);
    void clearPosition();

    face::StationFace *m_station;
    bool m_stale = true;
    QLabel *m_az;
    QLabel *m_el;
    QLabel *m_target;
    QLabel *m_status;
    QLabel *m_link = nullptr; // from afar only
    QLabel *m_pass = nullptr; // from afar only
};

} // namespace slew::ui
