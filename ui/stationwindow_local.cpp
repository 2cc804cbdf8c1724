// SPDX-License-Identifier: GPL-3.0-or-later
// The station window's local-only door (stationwindow.h): what only a
// station in this process has. The connection bar and the setup wizard; the
// Tracking tab (one target, upcoming passes, the schedule, the history),
// the Radio tab and the calibration, still built on the Station's parts
// until they are on the face; the register editor, the raw traffic and the
// rotctld trackers, which only a local link has; the other rotors of a
// multi-rotor controller; the alarm monitor's and the operator's lines in
// the event log; the menus; the window's saved layout.

#include "stationwindow.h"

#include "operatortheme.h"
#include "alarmbanner.h"
#include "rotor/configeditor.h"
#include "tracking/elementsetsdialog.h"
#include "rotor/connectionbar.h"
#include "widgets/elidinglabel.h"
#include "eventlog.h"
#include "rotor/gotopanel.h"
#include "history/historypanel.h"
#include "rotor/jogpad.h"
#include "keyboardcontrol.h"
#include "rotor/parkhomepanel.h"
#include "rotor/polarplotwidget.h"
#include "rotor/positionreadout.h"
#include "rotor/presetpanel.h"
#include "radio/radiopanel.h"
#include "tracking/schedulepanel.h"
#include "rotor/rotctldpanel.h"
#include "rotor/rotorspanel.h"
#include "tracking/stationdialog.h"
#include "stopbutton.h"
#include "rotor/targetconfirmation.h"
#include "telemetry/telemetrycharts.h"
#include "widgets/titledgroup.h"
#include "telemetry/telemetryrecorder.h"
#include "textfieldfocus.h"
#include "tracking/rehearsalmarker.h"
#include "tracking/timecontroller.h"
#include "rotor/trafficconsole.h"
#include "tracking/trackingline.h"
#include "tracking/trackingpanel.h"
#include "tracking/upcomingpanel.h"
#include "widgets/scrollablepage.h"
#include "wizard/setupwizard.h"
#include "rotor/alignmentpanel.h"
#include "operatoractions.h"
#include "windowstate.h"
#include "remote/remoteconnectdialog.h"

#include "bridge/rotctldserver.h"
#include "face/stationface.h"
#include "station/alarmmonitor.h"
#include "station/dopplerradio.h"
#include "station/passrecorder.h"
#include "station/schedulerunner.h"
#include "records/passrecordstore.h"
#include "station/station.h"
#include "session/controllerrotors.h"
#include "sky/elementsetsources.h"

#include <QDateTime>

#include <algorithm>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QScreen>
#include <QScrollArea>
#include <QStyle>
#include <QMenuBar>
#include <QCoreApplication>
#include <QMessageBox>
#include <QLabel>
#include <QSplitter>
#include <QSettings>
#include <QStatusBar>
#include <QTabWidget>
#include <QVBoxLayout>

namespace slew::ui {

using session::RotatorSession;

void StationWindow::openLocalDoor()
{
    station::Station *station = m_station;
    RotatorSession *session = m_session;
    m_connection = new ConnectionBar(session);
    m_alarms = station->alarms();
    // The charts in the station clock's time: a rehearsal's own.
    m_recorder->followClock(station->clock());
    m_charts->followClock(station->clock());
    connect(session, &RotatorSession::capabilitiesChanged, m_charts, [this](const session::Capabilities &caps) {
        // Until the probe has answered, everything is offered.
        m_charts->setReportsShown(!caps.probed || caps.inputs, !caps.probed || caps.status || caps.errors);
    });
    m_config = new ConfigEditor(session);
    m_traffic = new TrafficConsole(session);
    m_log->setClock(station->clock()); // a rehearsal's lines in its time
    m_rotctld = station->server();
    m_trackers = new RotctldPanel(m_rotctld);
    m_controllerRotors = station->controllerRotors();
    m_rotorsPanel = new RotorsPanel(m_controllerRotors);

    // Offline first: the last good copies, no network until asked.
    // The cache is read on worker threads: the window appears at once, and
    // the sets follow (ElementSetSources::loaded).
    m_elementSets = station->elementSets();
    m_elementSets->setUrls(sky::savedElementSetUrls());
    m_elementSets->loadFromCache();
    // A cached copy that cannot be used (over the cap, not a file) says so.
    connect(m_elementSets, &sky::ElementSetSources::loaded, this, [this] {
        for (const sky::ElementSetSourceStatus &s : m_elementSets->status())
            if (!s.error.isEmpty())
                m_log->addEvent(station::AlarmMonitor::Severity::Warning,
                                tr("element sets: %1: %2").arg(s.url.toString(), s.error));
    });
    // Whenever a refresh ends, from the dialog or elsewhere: each source
    // whose new copy was not taken says why.
    connect(m_elementSets, &sky::ElementSetSources::finished, this, [this] {
        int failed = 0;
        for (const sky::ElementSetSourceStatus &s : m_elementSets->status()) {
            if (!sky::sourceFailed(s))
                continue;
            ++failed;
            m_log->addEvent(station::AlarmMonitor::Severity::Warning,
                            tr("element sets: %1").arg(sky::describeSource(s)));
        }
        // Never "refreshed" when a source kept its old copy.
        logInfo(failed == 0 ? tr("element sets refreshed: %1 in all").arg(m_elementSets->sets().size())
                            : tr("element sets: %1 of %2 sources not refreshed (Sky → Element sets… says why); %3 in all")
                                  .arg(failed)
                                  .arg(m_elementSets->status().size())
                                  .arg(m_elementSets->sets().size()));
    });
    m_tracking = new TrackingPanel(station);
    m_alignment = new AlignmentPanel(session);
    // The Tracking tab: one target's passes and tracking, with below them
    // the calibration that tracking depends on; the schedule of several
    // targets by priority; and the record of the passes followed. Each a
    // page of its own: the window's tabs already fill a 1280-pixel screen.
    auto *oneTarget = new QWidget;
    oneTarget->setObjectName(QStringLiteral("oneTargetPage"));
    auto *trackingLayout = new QVBoxLayout(oneTarget);
    trackingLayout->addWidget(m_tracking, 1);
    trackingLayout->addWidget(m_alignment);
    m_trackingTabs = new QTabWidget;
    m_trackingTabs->setObjectName(QStringLiteral("trackingTabs"));
    m_trackingTabs->setDocumentMode(true);
    m_trackingTabs->addTab(scrollablePage(oneTarget), tr("One target"));
    // The favourites' next passes, soonest first; a double click opens one.
    m_upcoming = new UpcomingPanel(station);
    m_trackingTabs->addTab(scrollablePage(m_upcoming), tr("Upcoming"));
    connect(m_tracking, &TrackingPanel::favouritesChanged, m_upcoming, &UpcomingPanel::refresh);
    connect(m_upcoming, &UpcomingPanel::targetChosen, this, [this, oneTarget](const QString &name) {
        m_tracking->selectTarget(name);
        bringToFront(oneTarget);
    });
    m_trackingTabs->addTab(scrollablePage(m_schedule), tr("Schedule"));
    m_history = new HistoryPanel(station);
    m_trackingTabs->addTab(scrollablePage(m_history), tr("History"));
    // The radio has a tab of its own: its link, its frequencies and its
    // live lines do not fit beside the passes on a 720-pixel screen.
    m_radio = new RadioPanel(station);

    // Between the Telemetry and the Events (layOut): the pages only a
    // station in this process has.
    m_tabs->addTab(m_trackingTabs, tr("Tracking"));
    m_tabs->addTab(scrollablePage(m_radio), tr("Radio"));
    m_tabs->addTab(scrollablePage(m_config), tr("Configuration"));
    m_tabs->addTab(scrollablePage(m_traffic), tr("Traffic"));
    m_tabs->addTab(scrollablePage(m_trackers), tr("Trackers"));
    layOut(m_connection, m_rotorsPanel, nullptr);


    // Resting on a limit switch is a state: a quiet line at the foot of the
    // window, not the banner.
    auto *resting = new ElidingLabel;
    resting->setObjectName(QStringLiteral("limitSwitchState"));
    statusBar()->addPermanentWidget(resting);
    connect(m_alarms, &station::AlarmMonitor::restingChanged, resting, &ElidingLabel::setFullText);
    connect(m_connection, &ConnectionBar::disconnectRequested, m_alarms, &station::AlarmMonitor::expectDisconnect);
    // Stamped by the log's clock (a rehearsal's time during one), as every line.
    connect(m_alarms, &station::AlarmMonitor::eventLogged, m_log,
            [this](const QDateTime &, station::AlarmMonitor::Severity severity, const QString &text) {
                m_log->addEvent(severity, text);
            });
    connect(m_alarms, &station::AlarmMonitor::eventLogged, this,
            [this](const QDateTime &, station::AlarmMonitor::Severity, const QString &text) {
                // The resting state has its own place at the foot: the event
                // log keeps it, the passing message would only say it twice.
                if (!text.isEmpty() && m_alarms->resting().contains(text))
                    return;
                statusBar()->showMessage(text, 8000);
            });
    wireOperatorActions();
    connect(m_trackers, &RotctldPanel::message, this, &StationWindow::logInfo);
    connect(m_tracking, &TrackingPanel::message, this, &StationWindow::logInfo);
    connect(m_radio, &RadioPanel::message, this, &StationWindow::logInfo);
    // The schedule's decisions, as it makes them (a station on a broker
    // logs its own).
    if (station::ScheduleRunner *schedule = station->scheduleRunner())
        connect(schedule, &station::ScheduleRunner::logLine, this, &StationWindow::logInfo);
    connect(m_alignment, &AlignmentPanel::message, this, &StationWindow::logInfo);
    connect(m_history, &HistoryPanel::message, this, &StationWindow::logInfo);
    // Each pass's record, begun and finished, in the event log.
    if (station::PassRecorder *recorder = station->passRecorder())
        connect(recorder, &station::PassRecorder::logLine, this, &StationWindow::logInfo);
    connect(station->passRecords(), &records::PassRecordStore::writeFailed, this,
            [this](const QString &error) { reportProblem(tr("pass records: %1").arg(error)); });
    m_time = new TimeController(station, this);
    // The Tracking tab's "Rehearse this pass": from two minutes before its
    // AOS, with the Time controller shown to pause or step it.
    connect(m_tracking, &TrackingPanel::rehearsePassRequested, m_time, [this](double aosJulian) {
        m_time->rehearsePass(aosJulian);
        m_time->showController();
    });
    new RehearsalMarker(station->clock(), this);
    connect(m_tracking, &TrackingPanel::passOverlayChanged, m_plot, &PolarPlotWidget::setPassOverlay);
    connect(m_tracking, &TrackingPanel::passTargetMoved, m_plot, &PolarPlotWidget::setPassTarget);
    // What the tracker measures while it tracks is charted with the rest.
    connect(&station->passRunner()->tracker(), &tracking::Tracker::pointingError, m_recorder,
            &TelemetryRecorder::recordPointingError);
    // And what the radio measures while it tunes a pass.
    connect(station->radio(), &station::DopplerRadio::measured, m_recorder, &TelemetryRecorder::recordDopplerError);
    // The place the station keeps; the Tracking tab follows it by itself.
    connect(station, &station::Station::placeChanged, m_alignment, &AlignmentPanel::setStation);
    connect(station, &station::Station::placeChanged, m_plot, [this](const std::optional<sky::Site> &place) {
        m_plot->setHorizonMask(place ? place->horizon : nullptr);
    });
    if (const QString problem = station->restoreSavedPlace(); !problem.isEmpty())
        logInfo(problem);
    // Why the link failed stays at the foot of the window until the next
    // attempt, not only for the seconds a passing message lasts.
    auto *linkProblem = new QLabel;
    linkProblem->setObjectName(QStringLiteral("linkProblem"));
    linkProblem->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    linkProblem->setStyleSheet(warningText());
    statusBar()->addWidget(linkProblem, 1);
    connect(m_connection, &ConnectionBar::disconnectRequested, this, [this] { m_disconnectAsked = true; });
    connect(session, &RotatorSession::stateChanged, linkProblem,
            [this, linkProblem](RotatorSession::State s, const QString &detail) {
                const bool failed = s == RotatorSession::State::Reconnecting
                                    || (s == RotatorSession::State::Disconnected && !m_disconnectAsked);
                if (s == RotatorSession::State::Disconnected)
                    m_disconnectAsked = false;
                linkProblem->setText(failed && !detail.isEmpty() ? tr("Link: %1").arg(detail) : QString());
                linkProblem->setToolTip(linkProblem->text());
            });
    connect(session, &RotatorSession::stateChanged, this, [this](RotatorSession::State s) {
        if (s == RotatorSession::State::Disconnected)
            m_jog->releaseAll();
        setWindowTitle(s == RotatorSession::State::Disconnected ? tr("Slew")
                                                                : tr("Slew — %1").arg(m_session->uri()));
    });
    buildMenus();
    const QScreen *screen = QGuiApplication::primaryScreen();
    new WindowState(this, m_splitter, m_tabs, screen ? screen->availableGeometry() : QRect(0, 0, 1440, 900));
}

void StationWindow::buildMenus()
{
    // A station that lives on a broker opens in a window of its own.
    QMenu *file = menuBar()->addMenu(tr("&File"));
    QAction *openRemote = file->addAction(tr("Open &remote station…"));
    openRemote->setObjectName(QStringLiteral("actionOpenRemote"));
    connect(openRemote, &QAction::triggered, this, [this] {
        auto *dialog = new RemoteConnectDialog(this);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->open(); // window-modal, the event loop keeps running
    });
    QMenu *rotator = menuBar()->addMenu(tr("&Rotator"));
    QAction *wizard = rotator->addAction(tr("Setup and tuning &wizard…"));
    wizard->setObjectName(QStringLiteral("actionSetupWizard"));
    connect(wizard, &QAction::triggered, this, &StationWindow::openSetupWizard);
    rotator->addSeparator();
    // Quit stops the rotator first and closes once the stop has left the
    // link, as SIGTERM does: leaving never leaves the antenna moving.
    QAction *quit = rotator->addAction(tr("&Quit"));
    quit->setObjectName(QStringLiteral("actionQuit"));
    quit->setShortcut(QKeySequence::Quit);
    connect(quit, &QAction::triggered, this, [this] {
        logInfo(tr("quitting: stopping the rotator first"));
        connect(m_station, &station::Station::shutDown, this, &QWidget::close);
        m_station->shutdown(tr("quitting"));
    });

    QMenu *sky = menuBar()->addMenu(tr("&Sky"));
    QAction *station = sky->addAction(tr("&Station…"));
    station->setObjectName(QStringLiteral("actionStation"));
    connect(station, &QAction::triggered, this, [this] {
        auto *dialog = new StationDialog(this);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        connect(dialog, &QDialog::accepted, this, [this, dialog] {
            m_station->setPlace(dialog->station());
            logInfo(tr("station set to %1").arg(sky::siteLocator(dialog->station().latitudeDeg,
                                                                 dialog->station().longitudeDeg)));
            if (dialog->station().horizon)
                logInfo(tr("horizon mask: %1").arg(dialog->station().horizon->describe()));
        });
        dialog->open(); // window-modal, the event loop keeps running
    });
    QAction *sets = sky->addAction(tr("&Element sets…"));
    sets->setObjectName(QStringLiteral("actionElementSets"));
    connect(sets, &QAction::triggered, this, &StationWindow::openElementSets);
    QAction *time = sky->addAction(tr("&Time controller…"));
    time->setObjectName(QStringLiteral("actionTimeController"));
    connect(time, &QAction::triggered, m_time, &TimeController::showController);

    QMenu *help = menuBar()->addMenu(tr("&Help"));
    QAction *keys = help->addAction(tr("&Keyboard"));
    keys->setObjectName(QStringLiteral("actionKeyboard"));
    connect(keys, &QAction::triggered, this, [this] {
        showNote(tr("Keyboard"),
                 tr("<table cellspacing='6'>"
                    "<tr><td><b>Esc</b></td><td>Stop, always</td></tr>"
                    "<tr><td><b>Space</b></td><td>Stop; in a text field only while the rotator moves</td></tr>"
                    "<tr><td><b>Arrow keys</b></td><td>jog while held</td></tr>"
                    "<tr><td><b>1 to 9</b></td><td>go to that preset</td></tr>"
                    "<tr><td><b>Enter</b></td><td>in the go-to fields: go</td></tr>"
                    "<tr><td><b>Ctrl+D</b></td><td>in the target picker: keep as a favourite</td></tr>"
                    "<tr><td><b>Ctrl+Q</b></td><td>stop the rotator and quit</td></tr></table>"));
    });
    QAction *about = help->addAction(tr("&About Slew"));
    about->setObjectName(QStringLiteral("actionAbout"));
    connect(about, &QAction::triggered, this, [this] {
        showNote(tr("About Slew"),
                 tr("<b>Slew %1</b><p>A controller for az/el antenna rotators: Easycomm, GS-232, Micro-2g and "
                    "SPID controllers, rotctld trackers, pass planning and tracking.</p>"
                    "<p>Free software under the GNU General Public License, version 3 or later. "
                    "<code>man slew</code> describes every option.</p>")
                     .arg(QCoreApplication::applicationVersion()));
    });
}


void StationWindow::openElementSets()
{
    auto *dialog = new ElementSetsDialog(m_elementSets, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &ElementSetsDialog::ageLimitChanged, m_station, &station::Station::setElementAgeLimitDays);
    dialog->open();
}

void StationWindow::openSetupWizard()
{
    auto *wizard = new SetupWizard(m_session, this);
    wizard->setObjectName(QStringLiteral("setupWizard"));
    wizard->setAttribute(Qt::WA_DeleteOnClose);
    connect(wizard, &SetupWizard::profileSaved, this, [this](const QString &path) {
        logInfo(tr("setup wizard saved the rotator profile to %1").arg(path));
        if (const std::optional<face::StationState> state = m_face->state())
            showState(*state); // the travel and park it may have changed
    });
    wizard->open(); // window-modal, never from a timer: the event loop keeps running
}

void StationWindow::wireOperatorActions()
{
    m_actions = new OperatorActions(m_station->moveWatch(), this);
    connect(m_actions, &OperatorActions::logged, this, [this](station::AlarmMonitor::Severity severity, const QString &text) {
        m_log->addEvent(severity, text);
        statusBar()->showMessage(text, severity == station::AlarmMonitor::Severity::Info ? 8000 : 30000);
    });
    // The lines that say where a move is going clear when it ends.
    connect(m_actions, &OperatorActions::moveEnded, m_confirm, &TargetConfirmation::moveEnded);
    connect(m_actions, &OperatorActions::moveEnded, m_presets, &PresetPanel::moveEnded);
    connect(m_actions, &OperatorActions::moveEnded, m_parkHome, &ParkHomePanel::moveEnded);
    connect(m_goto, &GotoPanel::moveSent, m_actions, &OperatorActions::moveStarted);
    connect(m_presets, &PresetPanel::moveSent, m_actions, &OperatorActions::moveStarted);
    connect(m_parkHome, &ParkHomePanel::moveSent, m_actions, &OperatorActions::moveStarted);
    connect(m_parkHome, &ParkHomePanel::homingStarted, m_actions, [this] { m_actions->action(tr("home")); });
    connect(m_parkHome, &ParkHomePanel::homingFinished, m_actions,
            [this](bool ok, const QString &message) { m_actions->outcome(tr("home: %1").arg(message), !ok); });
    // Every stop that went out, whoever asked: the STOP button or a key, a
    // released jog, a rotctld client, MQTT, a lease run out, a limit reached.
    connect(m_session, &session::RotatorSession::stopSent, m_actions, [this](const QString &cause) {
        m_actions->action(tr("Stop (%1) at %2").arg(cause, describePosition(QPointF(m_session->azimuth(), m_session->elevation()))));
    });
    connect(m_jog, &JogPad::jogStarted, m_actions, &OperatorActions::action); // its release is a stop
}


void StationWindow::connectTo(const QString &uri, std::optional<protocol::Dialect> dialect)
{
    m_connection->setUri(uri);
    if (dialect)
        m_connection->setDialect(*dialect);
    m_connection->connectToRotator();
}

} // namespace slew::ui
