// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Sky → Time controller…: the station clock the window plans and tracks by,
// for rehearsing a pass and checking a plan as Gpredict's Time Controller
// does. Start the clock at a chosen UTC instant, run it 1 to 20 times
// faster, or go back to real time; pause it, step it forward while paused,
// or move it along the next hours with the slider; or rehearse a chosen
// pass from two minutes before its AOS. The Tracking tab's passes, the pass
// and the target on the plot, and a running tracker follow the clock (each
// plans again when it starts again; a pause or a step needs no new plan),
// and the built-in simulator keeps its pace (tracking/simulatorpace.h). A
// non-modal dialog: the window goes on working beside it, and closing it
// keeps the clock as it is.

#include "tracking/stationclock.h"

#include <QDialog>
#include <QTimer>

#include <optional>

class QLabel;
class QPushButton;
class QSlider;
class QSpinBox;

namespace slew::station {
class Station;
}
namespace slew::tracking {
class SimulatorPace;
}

namespace slew::ui {

class UtcTimeField;

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
    // A rehearsal of the pass with this AOS, at the rate in the field: the
    // clock starts kPassLeadSeconds before it, time enough for the rotator
    // to reach the AOS point as it would before a real pass.
    void rehearsePass(double aosJulian);
    static constexpr double kPassLeadSeconds = 120.0;
    // How far ahead the slider reaches from where it starts.
    static constexpr int kSliderMinutes = 12 * 60;

    UtcTimeField *startField() const { return m_start; }
    QSpinBox *rateField() const { return m_rate; }
    QPushButton *startButton() const { return m_startButton; }
    QPushButton *realTimeButton() const { return m_realTimeButton; }
    QPushButton *pauseButton() const { return m_pauseButton; }
    QSpinBox *stepField() const { return m_step; }
    QPushButton *stepButton() const { return m_stepButton; }
    QSlider *slider() const { return m_slider; }
    QLabel *sliderLine() const { return m_sliderLine; }
    QLabel *problemLine() const { return m_problem; }
    QLabel *stateLine() const { return m_state; }

public slots:
    // Sky → Time controller…: shown beside the window, and brought forward
    // when it is already open.
    void showController();

private:
    void startAsTyped();
    void onRateChosen(int rate);
    void togglePause();
    void onSliderMoved(int minutes);
    double sliderOrigin() const;
    void showState();
    void showSlider();

    tracking::StationClock *m_clock;
    const tracking::SimulatorPace *m_pace;
    UtcTimeField *m_start;
    QSpinBox *m_rate;
    QPushButton *m_startButton;
    QPushButton *m_realTimeButton;
    QPushButton *m_pauseButton;
    QSpinBox *m_step;
    QPushButton *m_stepButton;
    QSlider *m_slider;
    QLabel *m_sliderLine;
    QLabel *m_problem;
    QLabel *m_state;
    // Where the slider's hours start: the instant the rehearsal started
    // from here; none in real time (the slider then starts at now).
    std::optional<double> m_origin;
    QTimer m_tick;
};

} // namespace slew::ui
