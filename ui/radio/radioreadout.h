// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Radio panel's live lines while a satellite is tracked: its frequencies
// as applied (with the calibration), what the radio was last sent (receive
// and transmit), the Doppler shift now on each path and how fast it moves, how far the operator
// has moved the downlink (by the radio's dial or the tab's tuning), and the pass's Doppler figures
// (RMS and worst error, frequencies sent, the operator's offset). After LOS the last pass's figures and the last
// frequencies sent stay shown until the next pass is tuned.

#include "tracking/tracktarget.h"

#include <QTimer>
#include <QWidget>

#include <optional>

class QLabel;

namespace slew::station {
class Station;
}

namespace slew::ui {

class RadioReadout : public QWidget {
    Q_OBJECT
public:
    // The station must outlive the readout.
    explicit RadioReadout(station::Station *station, QWidget *parent = nullptr);

    // The line of what the radio was last sent (the wheel over it tunes).
    QWidget *sentLine() const;

public slots:
    void refresh();

private:
    void onSteering(bool steering);
    // Where the tracked satellite is now (its range-rate in km/s with it);
    // nothing when no satellite is tracked.
    std::optional<sky::LookAngles> lookNow();
    // The same satellite `seconds` from now (after lookNow()).
    std::optional<sky::LookAngles> lookIn(double seconds);

    station::Station *m_station;
    QLabel *m_nominal;
    QLabel *m_sent;
    QLabel *m_shift;
    QLabel *m_dial;
    QLabel *m_figures;
    QTimer m_tick;
    // The tracked satellite's sky, kept while the same one is tracked: its
    // propagation carries on from tick to tick.
    std::optional<tracking::TargetSky> m_sky;
    std::optional<double> m_lastReceive, m_lastTransmit; // held past LOS
    std::optional<double> m_lastDialHz;
};

} // namespace slew::ui
