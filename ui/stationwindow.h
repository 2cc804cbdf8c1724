#pragma once
// The station window: one class for every station, here or on a broker.
// Its frame is the same for both and sees the station only through its face
// (face/stationface.h): the alarm banner on top; the polar plot; the control
// column (position, go-to, jog, Stop and what is tracked, Park/Home,
// presets); the tabs with the live charts first and the event log last.
//
// What only one kind of station has comes through its door:
//   - local (stationwindow_local.cpp): the connection bar, the Tracking,
//     Radio, Configuration, Traffic and Trackers tabs, the other rotors of
//     a multi-rotor controller, the menus and the wizard; the pages that
//     still read the Station's parts live behind this door until they are
//     on the face;
//   - remote (remote/stationwindow_remote.cpp): the banner that says it is
//     remote and how old its state is, tracking by name, the station's
//     published schedule, and the broker's words in the event log.
// It holds no protocol state and makes no station part of its own.

#include "session/rotatorsession.h"

#include <QMainWindow>
#include <QPointF>
#include <QStringList>

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
namespace slew::face {
class StationFace;
struct StationPlan;
struct StationState;
}
namespace slew::remote {
class RemoteStation;
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
class RemoteBanner;
class RemoteControls;
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

class StationWindow : public QMainWindow {
    Q_OBJECT
public:
    // A station in this process, behind the local door. The station must
    // outlive the window.
    explicit StationWindow(station::Station *station, QWidget *parent = nullptr);
    // A station on a broker, behind the remote door. The station must
    // outlive the window (parent it to the window).
    explicit StationWindow(remote::RemoteStation *station, QWidget *parent = nullptr);

    // What every part of the frame shows and asks.
    face::StationFace *face() const { return m_face; }
    // The station behind the door that is open; null for the other.
    station::Station *station() const { return m_station; }
    remote::RemoteStation *remoteStation() const { return m_remote; }

    PositionReadout *readout() const { return m_readout; }

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
    // From afar: the banner, tracking by name, the published schedule.
    RemoteBanner *remoteBanner() const { return m_remoteBanner; }
    RemoteControls *controls() const { return m_controls; }

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
    // The frame, on the face.
    void makeSharedParts();
    // The frame laid out, with what the door adds: its bar across the top,
    // what goes under the plot and at the foot of the control column (either
    // may be null), its tabs already added between Telemetry and Events.
    void layOut(QWidget *topBar, QWidget *underPlot, QWidget *doorControls);
    QWidget *buildControlColumn(QWidget *doorControls);
    void showState(const face::StationState &state);
    void showLive(bool live);
    void showAlarms();
    // Where the station says the antenna goes, or `sent` until it says.
    QPointF targetOr(QPointF sent) const;
    void giveTheTabsTheirWidth();
    void onPresetKey(int index);
    void onTargetPicked(double az, double el);
    void sendPickedTarget(double az, double el);

    // The local door (stationwindow_local.cpp).
    void openLocalDoor();
    void wireOperatorActions();
    void buildMenus();

    // The remote door (remote/stationwindow_remote.cpp).
    void openRemoteDoor();
    void showPlan(const face::StationPlan &plan);
    void remoteLog(bool problem, const QString &text);
    void logNewAlarms(const QStringList &alarms);
    void logInfo(const QString &text);

    face::StationFace *m_face = nullptr;
    station::Station *m_station = nullptr;      // the local door's
    remote::RemoteStation *m_remote = nullptr; // the remote door's
    session::RotatorSession *m_session = nullptr;
    ConnectionBar *m_connection = nullptr;
    AlarmBanner *m_banner = nullptr;
    station::AlarmMonitor *m_alarms = nullptr;
    TelemetryRecorder *m_recorder = nullptr;
    PolarPlotWidget *m_plot = nullptr;
    TargetConfirmation *m_confirm = nullptr;
    PositionReadout *m_readout = nullptr;
    GotoPanel *m_goto = nullptr;
    JogPad *m_jog = nullptr;
    StopButton *m_stop = nullptr;
    TrackingLine *m_trackingLine = nullptr; // beside STOP: what is tracked, until when
    UpcomingPanel *m_upcoming = nullptr;
    ParkHomePanel *m_parkHome = nullptr;
    PresetPanel *m_presets = nullptr;
    TelemetryCharts *m_charts = nullptr;
    ConfigEditor *m_config = nullptr;
    TrafficConsole *m_traffic = nullptr;
    EventLog *m_log = nullptr;
    QTabWidget *m_tabs = nullptr;
    QSplitter *m_splitter = nullptr; // the plot, the controls, the tabs
    KeyboardControl *m_keys = nullptr;
    std::optional<int> m_askedPreset; // the preset the confirmation strip asks about
    OperatorActions *m_actions = nullptr;
    bool m_disconnectAsked = false; // the next Disconnected is the operator's, not a failure
    bridge::RotctldServer *m_rotctld = nullptr;
    RotctldPanel *m_trackers = nullptr;
    session::ControllerRotors *m_controllerRotors = nullptr;
    RotorsPanel *m_rotorsPanel = nullptr;
    TrackingPanel *m_tracking = nullptr;
    RadioPanel *m_radio = nullptr;
    SchedulePanel *m_schedule = nullptr;
    QTabWidget *m_trackingTabs = nullptr; // the Tracking tab: one target, the schedule
    AlignmentPanel *m_alignment = nullptr;
    HistoryPanel *m_history = nullptr;
    TimeController *m_time = nullptr;
    sky::ElementSetSources *m_elementSets = nullptr;
    // The remote door's.
    RemoteBanner *m_remoteBanner = nullptr;
    RemoteControls *m_controls = nullptr;
    QStringList m_lastAlarms;
};

} // namespace slew::ui
