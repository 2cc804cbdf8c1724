// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Beside STOP, on every page: what Slew's own tracking is doing and until
// when ("Tracking FO-29 until 15:32:10 UTC, 0:08:12 left"), in the
// station's time (a rehearsal's, during one). The words are the station's
// (face/trackingnow.h). A few short lines in the height of the button:
// the control column has no height to spare at 1280x720. It reads the
// station's state through its face, here or on a broker alike.

#include "face/trackingnow.h"

#include <QLabel>
#include <QTimer>

namespace slew::face {
class StationFace;
}

namespace slew::ui {

class TrackingLine : public QLabel {
    Q_OBJECT
public:
    // Read every second, and as the station's state changes.
    explicit TrackingLine(face::StationFace *station, QWidget *parent = nullptr);

    void refresh();

    // The line for `followed` at `nowJulian`.
    static QString textFor(const face::TrackingNow &followed, double nowJulian);
    // A count of seconds as the window's countdowns show it: "0:08:12".
    static QString countdown(double seconds);

private:
    face::StationFace *m_station;
    QTimer m_tick; // the countdown's second
};

} // namespace slew::ui
