// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The window for a station that lives on a broker (remote/remotestation.h):
// the operator window's own widgets where they are values — the polar plot,
// the alarm banner, the big Stop, the telemetry charts, the event log — and
// small remote counterparts of the panels that are views of a local
// session (the readout, go-to, jog, Park and Home, tracking). A banner
// across the top says it is remote, which station on which broker, and how
// old the last state is; a lost broker or a silent station greys it as a
// lost link greys the local window. Stop (the button, Esc, Space) always
// sends.

#include <QMainWindow>

class QTabWidget;

namespace slew::remote {
class RemoteStation;
}
namespace slew::face {
struct StationPlan;
struct StationState;
}

namespace slew::ui {

class AlarmBanner;
class EventLog;
class GotoPanel;
class JogPad;
class PositionReadout;
class PolarPlotWidget;
class RemoteBanner;
class RemoteControls;
class RemoteScheduleView;
class StopButton;
class TrackingLine;
class TelemetryCharts;
class TelemetryRecorder;

class RemoteStationWindow : public QMainWindow {
    Q_OBJECT
public:
    // The station must outlive the window (parent it to the window).
    explicit RemoteStationWindow(remote::RemoteStation *station, QWidget *parent = nullptr);

    remote::RemoteStation *station() const { return m_station; }
    RemoteBanner *remoteBanner() const { return m_remoteBanner; }
    AlarmBanner *alarmBanner() const { return m_alarms; }
    PolarPlotWidget *polarPlot() const { return m_plot; }
    PositionReadout *readout() const { return m_readout; }
    GotoPanel *gotoPanel() const { return m_goto; }
    JogPad *jogPad() const { return m_jog; }
    RemoteControls *controls() const { return m_controls; }
    StopButton *stopButton() const { return m_stop; }
    TrackingLine *trackingLine() const { return m_trackingLine; }
    TelemetryCharts *telemetryCharts() const { return m_charts; }
    EventLog *eventLog() const { return m_log; }
    RemoteScheduleView *scheduleView() const { return m_schedule; }

private:
    void showState(const face::StationState &state);
    void showPlan(const face::StationPlan &plan);
    void showLive(bool live);
    void log(bool problem, const QString &text);

    remote::RemoteStation *m_station;
    RemoteBanner *m_remoteBanner;
    AlarmBanner *m_alarms;
    PolarPlotWidget *m_plot;
    PositionReadout *m_readout;
    GotoPanel *m_goto;
    JogPad *m_jog;
    RemoteControls *m_controls;
    StopButton *m_stop;
    TrackingLine *m_trackingLine;
    TelemetryRecorder *m_recorder;
    TelemetryCharts *m_charts;
    EventLog *m_log;
    RemoteScheduleView *m_schedule;
    QTabWidget *m_tabs;
    QStringList m_lastAlarms;
};

} // namespace slew::ui
