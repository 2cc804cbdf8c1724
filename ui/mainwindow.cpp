// SPDX-License-Identifier: GPL-3.0-or-later
#include "mainwindow.h"

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
#include "station/alarmmonitor.h"
#include "station/dopplerradio.h"
#include "station/passrecorder.h"
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

MainWindow::MainWindow(station::Station *station, QWidget *parent)
    : QMainWindow(parent), m_station(station), m_session(station->session())
{
    setObjectName(QStringLiteral("mainWindow"));
    setWindowTitle(tr("Slew"));
    // The operator's limit, kept with the element sets' settings.
    station->setElementAgeLimitDays(ElementSetsDialog::savedAgeLimitDays());
    RotatorSession *session = m_session;
    m_connection = new ConnectionBar(session);
    m_banner = new AlarmBanner;
    m_alarms = station->alarms();
    m_recorder = new TelemetryRecorder(session, this);
    m_plot = new PolarPlotWidget;
    m_confirm = new TargetConfirmation;
    m_readout = new PositionReadout(station->face());
    m_goto = new GotoPanel(station->face());
    m_jog = new JogPad(station->face());
    m_stop = new StopButton([station](const QString &cause) { return bool(station->stop(cause)); });
    m_trackingLine = new TrackingLine(station->face());
    m_parkHome = new ParkHomePanel(station->face());
    m_presets = new PresetPanel(station->face());
    m_charts = new TelemetryCharts(&m_recorder->history());
    // The charts in the station clock's time: a rehearsal's own.
    m_recorder->followClock(station->clock());
    m_charts->followClock(station->clock());
    connect(session, &RotatorSession::capabilitiesChanged, m_charts, [this](const session::Capabilities &caps) {
        // Until the probe has answered, everything is offered.
        m_charts->setReportsShown(!caps.probed || caps.inputs, !caps.probed || caps.status || caps.errors);
    });
    m_config = new ConfigEditor(session);
    m_traffic = new TrafficConsole(session);
    m_log = new EventLog;
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
    m_schedule = new SchedulePanel(station);
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

    m_tabs = new QTabWidget;
    m_tabs->setObjectName(QStringLiteral("mainTabs"));
    // Each page scrolls where a small screen has less room than it needs.
    m_tabs->addTab(scrollablePage(m_charts), tr("Telemetry"));
    m_tabs->addTab(m_trackingTabs, tr("Tracking"));
    m_tabs->addTab(scrollablePage(m_radio), tr("Radio"));
    m_tabs->addTab(scrollablePage(m_config), tr("Configuration"));
    m_tabs->addTab(scrollablePage(m_traffic), tr("Traffic"));
    m_tabs->addTab(scrollablePage(m_trackers), tr("Trackers"));
    m_tabs->addTab(m_log, tr("Events"));

    auto *plotColumn = new QWidget;
    auto *plotLayout = new QVBoxLayout(plotColumn);
    plotLayout->setContentsMargins(0, 0, 0, 0);
    plotLayout->addWidget(m_plot, 1);
    plotLayout->addWidget(m_confirm);
    plotLayout->addWidget(m_rotorsPanel);

    auto *splitter = new QSplitter(Qt::Horizontal);
    splitter->setObjectName(QStringLiteral("mainSplitter"));
    splitter->addWidget(plotColumn);
    // The controls scroll up and down on a short screen, never sideways: the
    // scroll area keeps the column's width, and room for its bar.
    QWidget *column = buildControlColumn();
    ScrollablePage *controls = scrollablePage(column);
    controls->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    const int bar = controls->style()->pixelMetric(QStyle::PM_ScrollBarExtent);
    controls->setMinimumWidth(column->minimumWidth() + bar);
    controls->setMaximumWidth(column->maximumWidth() + bar);
    splitter->addWidget(controls);
    splitter->addWidget(m_tabs);
    // A wider window widens the plot and the tabs; the controls keep their width.
    splitter->setStretchFactor(0, 5);
    splitter->setStretchFactor(1, 0);
    splitter->setStretchFactor(2, 6);
    splitter->setChildrenCollapsible(false);

    auto *central = new QWidget;
    auto *layout = new QVBoxLayout(central);
    layout->setContentsMargins(6, 0, 6, 6);
    layout->setSpacing(4);
    layout->addWidget(m_connection);
    layout->addWidget(m_banner);
    layout->addWidget(splitter, 1);
    setCentralWidget(central);

    connect(m_alarms, &station::AlarmMonitor::alarmsChanged, m_banner, &AlarmBanner::showAlarms);
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
    connect(m_stop, &StopButton::stopped, m_jog, &JogPad::releaseAll);
    connect(m_stop, &StopButton::stopped, m_parkHome, &ParkHomePanel::abandonHoming);
    connect(m_stop, &StopButton::stopped, m_confirm, &TargetConfirmation::cancel);
    wireOperatorActions();
    connect(m_trackers, &RotctldPanel::message, this, &MainWindow::logInfo);
    connect(m_tracking, &TrackingPanel::message, this, &MainWindow::logInfo);
    connect(m_radio, &RadioPanel::message, this, &MainWindow::logInfo);
    connect(m_schedule, &SchedulePanel::message, this, &MainWindow::logInfo);
    connect(m_alignment, &AlignmentPanel::message, this, &MainWindow::logInfo);
    connect(m_history, &HistoryPanel::message, this, &MainWindow::logInfo);
    // Each pass's record, begun and finished, in the event log.
    if (station::PassRecorder *recorder = station->passRecorder())
        connect(recorder, &station::PassRecorder::logLine, this, &MainWindow::logInfo);
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
    connect(m_config, &ConfigEditor::profileChanged, this, &MainWindow::showProfile);
    connect(session, &RotatorSession::profileChanged, this, &MainWindow::showProfile);
    wirePlot();
    showProfile();
    m_keys = new KeyboardControl(this, m_stop, m_jog, this);
    connect(m_keys, &KeyboardControl::presetKey, this, &MainWindow::onPresetKey);
    // The plot takes no typing: the focus rests there after a go-to sent
    // with Enter and after a click beside a text field.
    new TextFieldFocus(this, m_plot, this);
    connect(m_goto, &GotoPanel::sentByEnter, m_plot, [this] { m_plot->setFocus(Qt::OtherFocusReason); });
    buildMenus();
    const QScreen *screen = QGuiApplication::primaryScreen();
    new WindowState(this, splitter, m_tabs, screen ? screen->availableGeometry() : QRect(0, 0, 1440, 900));
    // Whenever the splitter is laid out again: the tabs their pages' width.
    m_splitter = splitter;
    splitter->installEventFilter(this);
    QMetaObject::invokeMethod(this, &MainWindow::giveTheTabsTheirWidth, Qt::QueuedConnection);
}

void MainWindow::buildMenus()
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
    connect(wizard, &QAction::triggered, this, &MainWindow::openSetupWizard);
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
    connect(sets, &QAction::triggered, this, &MainWindow::openElementSets);
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

void MainWindow::showNote(const QString &title, const QString &html)
{
    // Window-modal and opened, not exec()'d: the event loop, and Stop, keep
    // running while it is up.
    auto *box = new QMessageBox(QMessageBox::Information, title, html, QMessageBox::Close, this);
    box->setTextFormat(Qt::RichText);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

void MainWindow::openElementSets()
{
    auto *dialog = new ElementSetsDialog(m_elementSets, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &ElementSetsDialog::ageLimitChanged, m_station, &station::Station::setElementAgeLimitDays);
    dialog->open();
}

void MainWindow::openSetupWizard()
{
    auto *wizard = new SetupWizard(m_session, this);
    wizard->setObjectName(QStringLiteral("setupWizard"));
    wizard->setAttribute(Qt::WA_DeleteOnClose);
    connect(wizard, &SetupWizard::profileSaved, this, [this](const QString &path) {
        logInfo(tr("setup wizard saved the rotator profile to %1").arg(path));
        showProfile();
    });
    wizard->open(); // window-modal, never from a timer: the event loop keeps running
}

void MainWindow::bringToFront(QWidget *page)
{
    // Every tab widget on the way up shows the page that holds it.
    for (QWidget *child = page; child && child != this; child = child->parentWidget()) {
        QWidget *stack = child->parentWidget();
        auto *tabs = stack ? qobject_cast<QTabWidget *>(stack->parentWidget()) : nullptr;
        if (tabs && tabs->indexOf(child) >= 0)
            tabs->setCurrentWidget(child);
    }
}

void MainWindow::giveTheTabsTheirWidth()
{
    // The pages scroll on a screen too narrow for them (1024x600); where
    // the plot can spare the width, they get what their widest page needs
    // not to scroll sideways, and the plot (a square, and the first to
    // grow) what is left, never below its least.
    int need = 0;
    for (const ScrollablePage *page : m_tabs->findChildren<ScrollablePage *>())
        need = std::max(need, page->pageLeastWidth());
    need += m_tabs->width() - m_tabs->currentWidget()->width(); // the tab widget's own frame
    QList<int> sizes = m_splitter->sizes();
    const int plotLeast = m_splitter->widget(0)->minimumSizeHint().width();
    if (sizes.size() != 3 || sizes[2] >= need || sizes[0] <= plotLeast)
        return;
    const int give = std::min(need - sizes[2], sizes[0] - plotLeast);
    sizes[0] -= give;
    sizes[2] += give;
    m_splitter->setSizes(sizes);
}

bool MainWindow::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_splitter && event->type() == QEvent::Resize)
        QMetaObject::invokeMethod(this, &MainWindow::giveTheTabsTheirWidth, Qt::QueuedConnection);
    return QMainWindow::eventFilter(watched, event);
}

void MainWindow::logInfo(const QString &text)
{
    m_log->addEvent(station::AlarmMonitor::Severity::Info, text);
    statusBar()->showMessage(text, 8000);
}

void MainWindow::reportProblem(const QString &text)
{
    m_log->addEvent(station::AlarmMonitor::Severity::Warning, text);
    statusBar()->showMessage(text, 30000);
}

QWidget *MainWindow::buildControlColumn()
{
    auto *column = new QWidget;
    column->setObjectName(QStringLiteral("controlColumn"));
    column->setMinimumWidth(300);
    column->setMaximumWidth(380);
    auto *l = new QVBoxLayout(column);
    l->setContentsMargins(4, 0, 4, 0);
    l->setSpacing(4);
    l->addWidget(titledGroup(tr("Position"), m_readout));
    l->addWidget(titledGroup(tr("Go to"), m_goto));
    l->addWidget(titledGroup(tr("Jog: hold, or arrow keys"), m_jog));
    // STOP, and beside it what Slew's tracking is doing: one row.
    auto *stopRow = new QHBoxLayout;
    stopRow->addWidget(m_stop, 1);
    stopRow->addWidget(m_trackingLine, 1);
    l->addLayout(stopRow);
    l->addWidget(m_parkHome);
    l->addWidget(titledGroup(tr("Presets"), m_presets), 1);
    return column;
}

void MainWindow::wirePlot()
{
    connect(m_session, &RotatorSession::positionChanged, m_plot, &PolarPlotWidget::setActual);
    connect(m_session, &RotatorSession::targetChanged, m_plot, &PolarPlotWidget::setTarget);
    connect(m_session, &RotatorSession::targetCleared, m_plot, &PolarPlotWidget::clearTarget);
    connect(m_session, &RotatorSession::commandedChanged, m_plot, &PolarPlotWidget::setCommanded);
    connect(m_session, &RotatorSession::stateChanged, m_plot, [this](RotatorSession::State s) {
        if (s == RotatorSession::State::Connecting)
            m_plot->clearPositions();
    });
    connect(m_session, &RotatorSession::parkChanged, this, &MainWindow::showPark);
    connect(m_plot, &PolarPlotWidget::targetPicked, this, &MainWindow::onTargetPicked);
    connect(m_confirm, &TargetConfirmation::pendingChanged, m_plot, &PolarPlotWidget::setPendingTarget);
    connect(m_confirm, &TargetConfirmation::accepted, this, &MainWindow::sendPickedTarget);
}

void MainWindow::onPresetKey(int index)
{
    // Alt+1..9. Without "Ask before moving" it goes at once, as a click on
    // the preset list does; with it, the strip under the plot asks first,
    // as for a click on the plot.
    const model::Preset *preset = m_presets->presets().at(index);
    if (!preset || !m_confirm->confirmationWanted()) {
        m_presets->recall(index); // says "There is no preset 4." where there is none
        return;
    }
    if (const model::MoveCheck check = m_session->previewPointing(preset->azimuth, preset->elevation); !check.allowed()) {
        m_confirm->showProblem(check.refusal);
        return;
    }
    m_askedPreset = index;
    m_confirm->ask(preset->azimuth, preset->elevation, tr("preset '%1'").arg(preset->name));
}

void MainWindow::onTargetPicked(double az, double el)
{
    m_askedPreset.reset();
    if (const model::MoveCheck check = m_session->previewPointing(az, el); !check.allowed()) {
        m_confirm->showProblem(check.refusal);
        return;
    }
    m_goto->setFields(az, el);
    if (m_confirm->confirmationWanted())
        m_confirm->ask(az, el);
    else
        sendPickedTarget(az, el);
}

void MainWindow::sendPickedTarget(double az, double el)
{
    // A preset asked for by its key goes as the preset (its name in the log).
    if (const std::optional<int> preset = std::exchange(m_askedPreset, std::nullopt)) {
        if (m_presets->recall(*preset))
            m_confirm->showGoing(m_session->targetAzimuth(), m_session->targetElevation());
        else
            m_confirm->cancel();
        return;
    }
    if (const session::CommandResult sent = m_session->gotoPosition(az, el); !sent) {
        m_confirm->showProblem(sent.refusal);
        return;
    }
    const QPointF target(m_session->targetAzimuth(), m_session->targetElevation());
    m_actions->moveStarted(tr("go to %1 (picked on the plot)").arg(describePosition(target)), target);
    m_confirm->showGoing(target.x(), target.y());
}

void MainWindow::wireOperatorActions()
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

void MainWindow::showProfile()
{
    // Both in the pointing frame, as the position is.
    m_plot->setLimits(m_session->moveGate().limits());
    showPark();
    m_charts->setElevationShown(!m_session->isAzimuthOnly());
}

void MainWindow::showPark()
{
    // In the pointing frame, as the position is; nothing until the
    // controller's registers have said where it parks.
    m_plot->setPark(m_session->parkKnown()
                        ? std::optional<QPointF>(QPointF(m_session->parkAzimuth(), m_session->parkElevation()))
                        : std::nullopt);
}

void MainWindow::connectTo(const QString &uri, std::optional<protocol::Dialect> dialect)
{
    m_connection->setUri(uri);
    if (dialect)
        m_connection->setDialect(*dialect);
    m_connection->connectToRotator();
}

} // namespace slew::ui
