// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Tuning across a linear transponder's passband from the Radio tab, as the
// radio's own dial does: step buttons, and the mouse wheel over the
// frequency the radio was sent. Each moves the operator's offset on the
// downlink (station/dopplerradio.h's tuneBy, the same offset a turn of the
// dial sets), the uplink following as the transponder maps it (the
// opposite way when it inverts), up to the passband's edges. Only during
// a pass under radio control; a step refused (at an edge, the hand on the
// dial) says why beside the buttons.

#include <QWidget>

class QLabel;

namespace slew::station {
class DopplerRadio;
}

namespace slew::ui {

class RadioPassbandTuner : public QWidget {
    Q_OBJECT
public:
    // What one notch of the wheel moves the downlink, Hz.
    static constexpr double kWheelStepHz = 100.0;

    // The radio must outlive the tuner.
    explicit RadioPassbandTuner(station::DopplerRadio *radio, QWidget *parent = nullptr);

    // The wheel over `widget` tunes too (the frequency line it sits by).
    void tuneWithWheelOver(QWidget *widget);

    // Moves the downlink by `hz`, as a button does; false with the reason shown when refused.
    bool tuneBy(double hz);

signals:
    void tuned(); // for the readout, which shows the offset at once

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void showEnabled();

    station::DopplerRadio *m_radio;
    QList<QWidget *> m_steps;
    QLabel *m_refusal;
    double m_wheelEighths = 0; // a fine wheel's part of a notch, until a whole one
};

} // namespace slew::ui
