#pragma once
// The operator window: connection bar and alarm banner on top; the polar
// plot; the control column (position, go-to, jog, Stop, Park/Home, presets);
// and tabs with the live charts, tracking, the radio, the config editor, the
// traffic console and the event log. It is a view of a Station (core/station/station.h): it
// wires widgets to the Station's parts and makes none of its own, and holds
// no protocol state.

#include "session/rotatorsession.h"

#include <QMainWindow>

#include <optional>

class QSplitter;
class QTabWidget;

namespace slew::bridge {
class RotctldServer;
}
namespace slew::station {
class AlarmMonitor;
class Station;
}

namespace slew::ui {

class AlarmBanner;
class AlignmentPanel;
class ConfigEditor;
class ConnectionBar;
class EventLog;
class GotoPanel;
class HistoryPanel;
class JogPad;
class KeyboardControl;
class OperatorActions;
class ParkHomePanel;
class PolarPlotWidget;
class PositionReadout;
class PresetPanel;
class RadioPanel;
class SchedulePanel;
class RotctldPanel;
class RotorsPanel;
class StopButton;
class TargetConfirmation;
class TelemetryCharts;
class TelemetryRecorder;
class TimeController;
class TrafficConsole;
class TrackingLine;
class TrackingPanel;
class UpcomingPanel;

}

namespace slew::sky {
class ElementSetSources;
}

namespace slew::session {
class ControllerRotors;
}

namespace slew::ui {

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    // The station must outlive the window.
    explicit MainWindow(station::Station *station, QWidget *parent = nullptr);

    station::Station *station() const { return m_station; }

    ConnectionBar *connectionBar() const { return m_connection; }
    PolarPlotWidget *polarPlot() const { return m_plot; }
    TargetConfirmation *targetConfirmation() const { return m_confirm; }
    GotoPanel *gotoPanel() const { return m_goto; }
    JogPad *jogPad() const { return m_jog; }
    StopButton *stopButton() const { return m_stop; }
    TrackingLine *trackingLine() const { return m_trackingLine; }
    UpcomingPanel *upcomingPanel() const { return m_upcoming; }
    ParkHomePanel *parkHomePanel() const { return m_parkHome; }
    PresetPanel *presetPanel() const { return m_presets; }
    TelemetryCharts *telemetryCharts() const { return m_charts; }
    ConfigEditor *configEditor() const { return m_config; }
    TrafficConsole *trafficConsole() const { return m_traffic; }
    AlarmBanner *alarmBanner() const { return m_banner; }
    station::AlarmMonitor *alarmMonitor() const { return m_alarms; }
    EventLog *eventLog() const { return m_log; }
    QTabWidget *tabs() const { return m_tabs; }
    // Shows the tab (or the page within a tab) that holds `page`.
    void bringToFront(QWidget *page);
    bridge::RotctldServer *rotctldServer() const { return m_rotctld; }
    RotctldPanel *rotctldPanel() const { return m_trackers; }
    // The other rotors of a multi-rotor controller, and their tiles.
    session::ControllerRotors *controllerRotors() const { return m_controllerRotors; }
    RotorsPanel *rotorsPanel() const { return m_rotorsPanel; }
    TrackingPanel *trackingPanel() const { return m_tracking; }
    // The station's radio: its link, the frequencies to tune, the pass's Doppler.
    RadioPanel *radioPanel() const { return m_radio; }
    SchedulePanel *schedulePanel() const { return m_schedule; }
    AlignmentPanel *alignmentPanel() const { return m_alignment; }
    // The passes the station recorded.
    HistoryPanel *historyPanel() const { return m_history; }
    // Sky → Time controller…: the station clock, and rehearsals.
    TimeController *timeController() const { return m_time; }
    // The element sets Slew knows, loaded from the cache at start.
    sky::ElementSetSources *elementSets() const { return m_elementSets; }

public slots:
    // Fills the connection bar with this URI (and dialect) and connects.
    void connectTo(const QString &uri, std::optional<slew::protocol::Dialect> dialect = std::nullopt);
    // Opens the setup and tuning wizard on this window's session.
    void openSetupWizard();
    // Sky → Element sets…
    void openElementSets();
    // A short note (keys, about) that leaves the window working.
    void showNote(const QString &title, const QString &html);
    // Something outside the rotator went wrong (the settings file could not
    // be read, ...): a warning in the event log and the status bar.
    void reportProblem(const QString &text);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override; // the splitter laid out again

private:
    QWidget *buildControlColumn();
    void giveTheTabsTheirWidth();
    void wirePlot();
    void onPresetKey(int index);
    void onTargetPicked(double az, double el);
    void sendPickedTarget(double az, double el);
    void wireOperatorActions();
    void showProfile();
    void showPark(); // the plot's P: the controller's park, once known
    void buildMenus();
    void logInfo(const QString &text);

    station::Station *m_station;
    session::RotatorSession *m_session;
    ConnectionBar *m_connection;
    AlarmBanner *m_banner;
    station::AlarmMonitor *m_alarms;
    TelemetryRecorder *m_recorder;
    PolarPlotWidget *m_plot;
    TargetConfirmation *m_confirm;
    PositionReadout *m_readout;
    GotoPanel *m_goto;
    JogPad *m_jog;
    StopButton *m_stop;
    TrackingLine *m_trackingLine; // beside STOP: what is tracked, until when
    UpcomingPanel *m_upcoming;
    ParkHomePanel *m_parkHome;
    PresetPanel *m_presets;
    TelemetryCharts *m_charts;
    ConfigEditor *m_config;
    TrafficConsole *m_traffic;
    EventLog *m_log;
    QTabWidget *m_tabs;
    QSplitter *m_splitter = nullptr; // the plot, the controls, the tabs
    KeyboardControl *m_keys;
    std::optional<int> m_askedPreset; // the preset the confirmation strip asks about
    OperatorActions *m_actions = nullptr;
    bool m_disconnectAsked = false; // the next Disconnected is the operator's, not a failure
    bridge::RotctldServer *m_rotctld;
    RotctldPanel *m_trackers;
    session::ControllerRotors *m_controllerRotors;
    RotorsPanel *m_rotorsPanel;
    TrackingPanel *m_tracking;
    RadioPanel *m_radio;
    SchedulePanel *m_schedule;
    QTabWidget *m_trackingTabs; // the Tracking tab: one target, the schedule
    AlignmentPanel *m_alignment;
    HistoryPanel *m_history;
    TimeController *m_time;
    sky::ElementSetSources *m_elementSets;
};

} // namespace slew::ui
