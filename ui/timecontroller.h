// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Sky → Time controller…: the station clock the window plans and tracks by,
// for rehearsing a pass and checking a plan as Gpredict's Time Controller
// does. Start the clock at a chosen UTC instant, run it 1 to 20 times
// faster, or go back to real time. The Tracking tab's passes, the pass and
// the target on the plot, and a running tracker follow the clock (each plans
// again when it changes), and the built-in simulator keeps its pace
// (tracking/simulatorpace.h). A non-modal dialog: the window goes on
// working beside it, and closing it keeps the clock as it is.

#include "tracking/stationclock.h"

#include <QDialog>
#include <QTimer>

class QDateTimeEdit;
class QLabel;
class QPushButton;
class QSpinBox;

namespace slew::station {
class Station;
}
namespace slew::tracking {
class SimulatorPace;
}

namespace slew::ui {

class TimeController : public QDialog {
    Q_OBJECT
public:
    // Sets the station's clock (and with it the pace of its simulator); the
    // station must outlive this.
    explicit TimeController(station::Station *station, QWidget *parent = nullptr);

    // The station clock: real time until a rehearsal starts.
    const tracking::StationClock *clock() const { return m_clock; }

    // A rehearsal from `startJulian` at `rate` (the command line's
    // --clock-start and --clock-rate, or Start here); the fields show it.
    void rehearse(double startJulian, double rate);
    void followRealTime();

    QDateTimeEdit *startField() const { return m_start; }
    QSpinBox *rateField() const { return m_rate; }
    QPushButton *startButton() const { return m_startButton; }
    QPushButton *realTimeButton() const { return m_realTimeButton; }
    QLabel *stateLine() const { return m_state; }

public slots:
    // Sky → Time controller…: shown beside the window, and brought forward
    // when it is already open.
    void showController();

private:
    void onRateChosen(int rate);
    void showState();

    tracking::StationClock *m_clock;
    const tracking::SimulatorPace *m_pace;
    QDateTimeEdit *m_start;
    QSpinBox *m_rate;
    QPushButton *m_startButton;
    QPushButton *m_realTimeButton;
    QLabel *m_state;
    QTimer m_tick;
};

} // namespace slew::ui
