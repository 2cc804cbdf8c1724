// SPDX-License-Identifier: GPL-3.0-or-later
// The station window's frame, the same for every station (stationwindow.h);
// the doors are stationwindow_local.cpp and remote/stationwindow_remote.cpp.
#include "stationwindow.h"

#include "alarmbanner.h"
#include "eventlog.h"
#include "keyboardcontrol.h"
#include "operatoractions.h"
#include "rotor/gotopanel.h"
#include "rotor/jogpad.h"
#include "rotor/parkhomepanel.h"
#include "rotor/polarplotwidget.h"
#include "rotor/positionreadout.h"
#include "rotor/presetpanel.h"
#include "rotor/targetconfirmation.h"
#include "stopbutton.h"
#include "telemetry/telemetrycharts.h"
#include "telemetry/telemetryrecorder.h"
#include "textfieldfocus.h"
#include "tracking/elementsetsdialog.h"
#include "tracking/schedulepanel.h"
#include "tracking/trackingline.h"
#include "widgets/scrollablepage.h"
#include "widgets/titledgroup.h"

#include "face/stationface.h"
#include "remote/remotestation.h"
#include "station/station.h"

#include <QHBoxLayout>
#include <QMessageBox>
#include <QSplitter>
#include <QStatusBar>
#include <QStyle>
#include <QTabWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace slew::ui {

using session::RotatorSession;

StationWindow::StationWindow(station::Station *station, QWidget *parent)
    : QMainWindow(parent), m_face(station->face()), m_station(station), m_session(station->session())
{
    setObjectName(QStringLiteral("mainWindow"));
    setWindowTitle(tr("Slew"));
    // The operator's limit, kept with the element sets' settings.
    station->setElementAgeLimitDays(ElementSetsDialog::savedAgeLimitDays());
    makeSharedParts();
    openLocalDoor();
}

StationWindow::StationWindow(remote::RemoteStation *station, QWidget *parent)
    : QMainWindow(parent), m_face(station), m_remote(station)
{
    setObjectName(QStringLiteral("remoteStationWindow"));
    setWindowTitle(tr("Slew — REMOTE station %1 on %2").arg(station->name(), station->brokerDisplay()));
    makeSharedParts();
    openRemoteDoor();
}

void StationWindow::makeSharedParts()
{
    face::StationFace *station = m_face;
    m_banner = new AlarmBanner;
    // From afar the face's telemetry feeds the charts (openRemoteDoor).
    m_recorder = new TelemetryRecorder(m_session, this);
    m_plot = new PolarPlotWidget;
    m_confirm = new TargetConfirmation;
    m_readout = new PositionReadout(station);
    m_goto = new GotoPanel(station);
    m_jog = new JogPad(station);
    // Stop always sends, live or not: a broker that is back takes it at once.
    m_stop = new StopButton([station](const QString &cause) { return station->stop(cause).isAccepted(); });
    m_trackingLine = new TrackingLine(station);
    m_parkHome = new ParkHomePanel(station);
    m_presets = new PresetPanel(station);
    // The Tracking tab's Schedule page, placed by each door.
    m_schedule = new SchedulePanel(station);
    m_charts = new TelemetryCharts(&m_recorder->history());
    m_log = new EventLog;
    m_tabs = new QTabWidget;
    m_tabs->setObjectName(QStringLiteral("mainTabs"));

    connect(m_stop, &StopButton::stopped, m_jog, &JogPad::releaseAll);
    connect(m_stop, &StopButton::stopped, m_parkHome, &ParkHomePanel::abandonHoming);
    connect(m_stop, &StopButton::stopped, m_confirm, &TargetConfirmation::cancel);
    connect(station, &face::StationFace::stateChanged, this, &StationWindow::showState);
    connect(station, &face::StationFace::liveChanged, this, &StationWindow::showLive);
    // The telemetry carries the position at the poll rate (from afar, the
    // state while the antenna only moves, once a second) and the commanded.
    connect(station, &face::StationFace::telemetryReceived, m_plot, [this](const face::TelemetrySample &s) {
        if (s.commandedAz && s.commandedEl)
            m_plot->setCommanded(*s.commandedAz, *s.commandedEl);
        if (s.az && s.el) {
            const std::optional<face::StationState> state = m_face->state();
            m_plot->setActual(*s.az, *s.el, !m_face->isLive() || (state && state->stale));
        }
    });
    connect(m_plot, &PolarPlotWidget::targetPicked, this, &StationWindow::onTargetPicked);
    connect(m_confirm, &TargetConfirmation::pendingChanged, m_plot, &PolarPlotWidget::setPendingTarget);
    connect(m_confirm, &TargetConfirmation::accepted, this, &StationWindow::sendPickedTarget);
    m_keys = new KeyboardControl(this, m_stop, m_jog, this);
    connect(m_keys, &KeyboardControl::presetKey, this, &StationWindow::onPresetKey);
    // The plot takes no typing: the focus rests there after a go-to sent
    // with Enter and after a click beside a text field.
    new TextFieldFocus(this, m_plot, this);
    connect(m_schedule, &SchedulePanel::message, this, &StationWindow::logInfo);
    connect(m_goto, &GotoPanel::sentByEnter, m_plot, [this] { m_plot->setFocus(Qt::OtherFocusReason); });
    if (const std::optional<face::StationState> state = station->state())
        showState(*state);
}

void StationWindow::showState(const face::StationState &s)
{
    // Both in the pointing frame, as the position is.
    m_plot->setLimits(s.limits);
    // Nothing until the controller's registers have said where it parks.
    m_plot->setPark(s.park);
    if (s.link == u"connecting") {
        m_plot->clearPositions(); // a new connection: forget the old rotator
    } else {
        if (s.position)
            m_plot->setActual(s.position->x(), s.position->y(), s.stale || !m_face->isLive());
        if (s.target)
            m_plot->setTarget(s.target->x(), s.target->y());
        else
            m_plot->clearTarget();
    }
    m_charts->setElevationShown(!s.azimuthOnly);
    showAlarms();
}

void StationWindow::showLive(bool live)
{
    m_jog->setEnabled(live);
    if (!live)
        m_jog->releaseAll();
    if (const std::optional<face::StationState> s = m_face->state(); s && s->position)
        m_plot->setActual(s->position->x(), s->position->y(), s->stale || !live);
    showAlarms();
}

void StationWindow::showAlarms()
{
    const std::optional<face::StationState> s = m_face->state();
    QStringList alarms = s ? s->alarms : QStringList();
    if (!m_face->isLive()) {
        // What the station said last still shows, dimmed; the banner says why.
        alarms.prepend(tr("Not live: %1").arg(m_face->whyNotLive()));
        m_banner->showAlarms(alarms, true);
        return;
    }
    m_banner->showAlarms(alarms, s && s->severe);
}

void StationWindow::layOut(QWidget *topBar, QWidget *underPlot, QWidget *doorControls)
{
    // Each page scrolls where a small screen has less room than it needs.
    m_tabs->insertTab(0, scrollablePage(m_charts), tr("Telemetry"));
    m_tabs->addTab(m_log, tr("Events"));
    m_tabs->setCurrentIndex(0);

    auto *plotColumn = new QWidget;
    auto *plotLayout = new QVBoxLayout(plotColumn);
    plotLayout->setContentsMargins(0, 0, 0, 0);
    plotLayout->addWidget(m_plot, 1);
    plotLayout->addWidget(m_confirm);
    if (underPlot)
        plotLayout->addWidget(underPlot);

    auto *splitter = new QSplitter(Qt::Horizontal);
    splitter->setObjectName(QStringLiteral("mainSplitter"));
    splitter->addWidget(plotColumn);
    // The controls scroll up and down on a short screen, never sideways: the
    // scroll area keeps the column's width, and room for its bar.
    QWidget *column = buildControlColumn(doorControls);
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
    layout->addWidget(topBar);
    layout->addWidget(m_banner);
    layout->addWidget(splitter, 1);
    setCentralWidget(central);
    // Whenever the splitter is laid out again: the tabs their pages' width.
    m_splitter = splitter;
    splitter->installEventFilter(this);
    QMetaObject::invokeMethod(this, &StationWindow::giveTheTabsTheirWidth, Qt::QueuedConnection);
}
void StationWindow::showNote(const QString &title, const QString &html)
{
    // Window-modal and opened, not exec()'d: the event loop, and Stop, keep
    // running while it is up.
    auto *box = new QMessageBox(QMessageBox::Information, title, html, QMessageBox::Close, this);
    box->setTextFormat(Qt::RichText);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

void StationWindow::bringToFront(QWidget *page)
{
    // Every tab widget on the way up shows the page that holds it.
    for (QWidget *child = page; child && child != this; child = child->parentWidget()) {
        QWidget *stack = child->parentWidget();
        auto *tabs = stack ? qobject_cast<QTabWidget *>(stack->parentWidget()) : nullptr;
        if (tabs && tabs->indexOf(child) >= 0)
            tabs->setCurrentWidget(child);
    }
}

void StationWindow::giveTheTabsTheirWidth()
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

bool StationWindow::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_splitter && event->type() == QEvent::Resize)
        QMetaObject::invokeMethod(this, &StationWindow::giveTheTabsTheirWidth, Qt::QueuedConnection);
    return QMainWindow::eventFilter(watched, event);
}

void StationWindow::logInfo(const QString &text)
{
    m_log->addEvent(station::AlarmMonitor::Severity::Info, text);
    statusBar()->showMessage(text, 8000);
}

void StationWindow::reportProblem(const QString &text)
{
    m_log->addEvent(station::AlarmMonitor::Severity::Warning, text);
    statusBar()->showMessage(text, 30000);
}

QWidget *StationWindow::buildControlColumn(QWidget *doorControls)
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
    if (doorControls)
        l->addWidget(doorControls);
    return column;
}

void StationWindow::onPresetKey(int index)
{
    // Alt+1..9. Without "Ask before moving" it goes at once, as a click on
    // the preset list does; with it, the strip under the plot asks first,
    // as for a click on the plot.
    const model::Preset *preset = m_presets->presets().at(index);
    if (!preset || !m_confirm->confirmationWanted()) {
        m_presets->recall(index); // says "There is no preset 4." where there is none
        return;
    }
    if (const model::MoveCheck check = m_face->previewPointing(preset->azimuth, preset->elevation); !check.allowed()) {
        m_confirm->showProblem(check.refusal);
        return;
    }
    m_askedPreset = index;
    m_confirm->ask(preset->azimuth, preset->elevation, tr("preset '%1'").arg(preset->name));
}

void StationWindow::onTargetPicked(double az, double el)
{
    m_askedPreset.reset();
    if (const model::MoveCheck check = m_face->previewPointing(az, el); !check.allowed()) {
        m_confirm->showProblem(check.refusal);
        return;
    }
    m_goto->setFields(az, el);
    if (m_confirm->confirmationWanted())
        m_confirm->ask(az, el);
    else
        sendPickedTarget(az, el);
}

void StationWindow::sendPickedTarget(double az, double el)
{
    // A preset asked for by its key goes as the preset (its name in the log).
    if (const std::optional<int> preset = std::exchange(m_askedPreset, std::nullopt)) {
        const model::Preset *p = m_presets->presets().at(*preset);
        if (p && m_presets->recall(*preset)) {
            const QPointF going = targetOr(QPointF(p->azimuth, p->elevation));
            m_confirm->showGoing(going.x(), going.y());
        } else {
            m_confirm->cancel();
        }
        return;
    }
    const face::Outcome sent = m_face->gotoPosition(az, el);
    if (sent.isRefused()) {
        m_confirm->showProblem(sent.reason());
        return;
    }
    const QPointF target = sent.isDone() ? targetOr(QPointF(az, el)) : QPointF(az, el);
    if (m_actions)
        m_actions->moveStarted(tr("go to %1 (picked on the plot)").arg(describePosition(target)), target);
    m_confirm->showGoing(target.x(), target.y());
}

QPointF StationWindow::targetOr(QPointF sent) const
{
    // Where the station says it is sending the antenna, once it says.
    const std::optional<face::StationState> s = m_face->state();
    return s && s->target ? *s->target : sent;
}

} // namespace slew::ui
