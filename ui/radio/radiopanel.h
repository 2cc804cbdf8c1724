// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Radio tab: the station's radio (station/dopplerradio.h) as the
// operator sets it up and watches it. Three parts, each its own widget:
//
//   - the link (radiolinkbox.h): which radio, Connect, its state; and
//     its VFOs and whether it is put back after LOS (radiovfochoice.h);
//   - what to tune (radioplanform.h), by hand or from one of the tracked
//     satellite's transponders (the station's cache, refreshed when the
//     operator asks, from the sources kept in radiotransponderdialog.h and
//     those another Slew saves), applied to the radio for the satellite tracked (or
//     any satellite, when none is) and kept in the settings per satellite:
//     tracking a satellite again brings its frequencies and offsets back,
//     and applies them; one with none kept gets its default transponder
//     filled in, to Apply;
//   - the live lines of a pass (radioreadout.h), and Stop radio control:
//     the operator's hands back on the radio, until resumed; and tuning
//     across the passband from the tab (radiopassbandtuner.h).
//
// The Doppler error the radio measures is charted on the Telemetry tab,
// under the pointing error (the window wires it to the recorder).

#include "radio/radioplan.h"

#include <QTimer>
#include <QWidget>

#include <optional>

class QGroupBox;
class QLabel;
class QPushButton;

namespace slew::station {
class Station;
}

namespace slew::ui {

class RadioLinkBox;
class RadioPlanForm;
class RadioReadout;
class RadioTransponderDialog;

class RadioPanel : public QWidget {
    Q_OBJECT
public:
    // The station must outlive the panel. Restores the kept radio and the
    // frequencies applied last.
    explicit RadioPanel(station::Station *station, QWidget *parent = nullptr);

    RadioLinkBox *linkBox() const { return m_link; }
    RadioPlanForm *planForm() const { return m_form; }
    RadioReadout *readout() const { return m_readout; }

    // Applies the fields to the radio, as the Apply button does: false,
    // with the refusals shown and the radio's plan unchanged, when a field
    // is bad.
    bool apply();

signals:
    void message(const QString &text); // for the event log

private:
    // The NORAD number of the satellite tracked now; 0 when none is.
    int trackedNorad() const;
    QString describeSatellite(int noradId) const;
    void onTracking();
    void showTransponders();
    void refreshTransponders();
    void showTransponderSources();
    // The last refresh's outcome on the tab: every source fine, or which not and why.
    void showRefreshResult();
    void showTransponderState(const QString &text, const QString &colour);
    void showPlanState();

    station::Station *m_station;
    RadioLinkBox *m_link;
    RadioPlanForm *m_form;
    RadioReadout *m_readout;
    QGroupBox *m_planBox;
    QPushButton *m_apply;
    QLabel *m_planState;
    QLabel *m_transponderState;
    RadioTransponderDialog *m_sourcesDialog = nullptr;
    int m_tracked = 0; // the satellite whose frequencies the fields were last given for
    bool m_refused = false;
    QTimer m_watch;
};

} // namespace slew::ui
