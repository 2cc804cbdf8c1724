// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Beside STOP, on every page: what Slew's own tracking is doing and until
// when ("Tracking FO-29 until 15:32:10 UTC, 0:08:12 left"), in the
// station's time (a rehearsal's, during one). The words are the station's
// (station/trackingnow.h). A few short lines in the height of the button:
// the control column has no height to spare at 1280x720. The local window
// reads its own station; a remote window, the state the station publishes.

#include "station/trackingnow.h"

#include <QLabel>
#include <QTimer>

#include <functional>

namespace slew::station {
class Station;
}

namespace slew::ui {

class TrackingLine : public QLabel {
    Q_OBJECT
public:
    // What is followed, and the station's time (a Julian date) to count by.
    struct Reading {
        station::TrackingNow followed;
        double nowJulian = 0;
    };
    // Read every second, and at refresh().
    explicit TrackingLine(std::function<Reading()> read, QWidget *parent = nullptr);
    // This station's tracking, also refreshed as it changes.
    explicit TrackingLine(station::Station *station, QWidget *parent = nullptr);

    void refresh();

    // The line for `followed` at `nowJulian`.
    static QString textFor(const station::TrackingNow &followed, double nowJulian);
    // A count of seconds as the window's countdowns show it: "0:08:12".
    static QString countdown(double seconds);

private:
    std::function<Reading()> m_read;
    QTimer m_tick; // the countdown's second
};

} // namespace slew::ui
