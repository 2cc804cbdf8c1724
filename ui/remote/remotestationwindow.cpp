// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/remotestationwindow.h"

#include "alarmbanner.h"
#include "eventlog.h"
#include "rotor/polarplotwidget.h"
#include "remote/remotebanner.h"
#include "remote/remotecontrols.h"
#include "rotor/passoverlay.h"
#include "remote/remotescheduleview.h"
#include "rotor/gotopanel.h"
#include "rotor/jogpad.h"
#include "rotor/positionreadout.h"
#include "stopbutton.h"
#include "telemetry/telemetrycharts.h"
#include "widgets/titledgroup.h"
#include "telemetry/telemetryrecorder.h"
#include "tracking/trackingline.h"

#include "remote/remotestation.h"

#include <QDateTime>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QScreen>
#include <QShortcut>
#include <QSplitter>
#include <QStatusBar>
#include <QTabWidget>
#include <QVBoxLayout>

namespace slew::ui {

using remote::RemoteStation;
using station::AlarmMonitor;

RemoteStationWindow::RemoteStationWindow(RemoteStation *station, QWidget *parent)
    : QMainWindow(parent), m_station(station)
{
    setObjectName(QStringLiteral("remoteStationWindow"));
    setWindowTitle(tr("Slew — REMOTE station %1 on %2").arg(station->name(), station->brokerDisplay()));
    m_remoteBanner = new RemoteBanner(station);
    m_alarms = new AlarmBanner;
    m_plot = new PolarPlotWidget;
    m_readout = new PositionReadout(station);
    // Go-to and jog are the local window's own panels, on the station's face.
    m_goto = new GotoPanel(station);
    m_jog = new JogPad(station);
    m_controls = new RemoteControls(station);
    // Stop always sends, live or not: a broker that is back takes it at once.
    // The station logs "a stop over MQTT": the cause stays here.
    m_stop = new StopButton([station](const QString &cause) { return station->stop(cause).isAccepted(); });
    m_trackingLine = new TrackingLine(station);
    m_recorder = new TelemetryRecorder(nullptr, this);
    m_charts = new TelemetryCharts(&m_recorder->history());
    m_log = new EventLog;

    m_tabs = new QTabWidget;
    m_tabs->setObjectName(QStringLiteral("remoteTabs"));
    m_tabs->addTab(m_charts, tr("Telemetry"));
    m_tabs->addTab(m_log, tr("Events"));
    m_schedule = new RemoteScheduleView;
    m_tabs->addTab(m_schedule, tr("Schedule"));

    auto *column = new QWidget;
    column->setObjectName(QStringLiteral("remoteControlColumn"));
    column->setMinimumWidth(320);
    column->setMaximumWidth(420);
    auto *columnLayout = new QVBoxLayout(column);
    columnLayout->setContentsMargins(4, 0, 4, 0);
    columnLayout->addWidget(titledGroup(tr("Position"), m_readout));
    columnLayout->addWidget(titledGroup(tr("Go to"), m_goto));
    columnLayout->addWidget(titledGroup(tr("Jog (hold)"), m_jog));
    columnLayout->addWidget(titledGroup(tr("Control"), m_controls));
    // As in the local window: what the station's tracking does, beside STOP.
    auto *stopRow = new QHBoxLayout;
    stopRow->setSpacing(6);
    stopRow->addWidget(m_stop, 1);
    stopRow->addWidget(m_trackingLine, 1);
    columnLayout->addLayout(stopRow);
    columnLayout->addStretch(1);

    auto *splitter = new QSplitter(Qt::Horizontal);
    splitter->addWidget(m_plot);
    splitter->addWidget(column);
    splitter->addWidget(m_tabs);
    splitter->setStretchFactor(0, 5);
    splitter->setStretchFactor(1, 0);
    splitter->setStretchFactor(2, 6);
    splitter->setChildrenCollapsible(false);

    auto *central = new QWidget;
    auto *layout = new QVBoxLayout(central);
    layout->setContentsMargins(6, 0, 6, 6);
    layout->setSpacing(4);
    layout->addWidget(m_remoteBanner);
    layout->addWidget(m_alarms);
    layout->addWidget(splitter, 1);
    setCentralWidget(central);

    connect(station, &RemoteStation::stateChanged, this, &RemoteStationWindow::showState);
    connect(station, &RemoteStation::liveChanged, this, &RemoteStationWindow::showLive);
    connect(station, &RemoteStation::telemetryReceived, m_recorder, &TelemetryRecorder::recordRemote);
    // The telemetry carries the position at the poll rate; the state, while
    // the antenna only moves, once a second.
    connect(station, &RemoteStation::telemetryReceived, m_plot, [this](const face::TelemetrySample &s) {
        if (s.commandedAz && s.commandedEl)
            m_plot->setCommanded(*s.commandedAz, *s.commandedEl);
        if (s.az && s.el) {
            const bool stale = !m_station->isLive() || (m_station->state() && m_station->state()->stale);
            m_plot->setActual(*s.az, *s.el, stale);
        }
    });
    connect(m_plot, &PolarPlotWidget::targetPicked, m_goto, &GotoPanel::setFields);
    connect(station, &RemoteStation::planChanged, this, &RemoteStationWindow::showPlan);
    connect(station, &RemoteStation::scheduleChanged, this, [this](const face::StationSchedule &s) {
        m_schedule->showSchedule(s, QDateTime::currentMSecsSinceEpoch());
    });
    // The time line's now moves with every state (at least every 5 s): no
    // timer of its own.
    connect(station, &RemoteStation::stateChanged, this,
            [this] { m_schedule->showTime(QDateTime::currentMSecsSinceEpoch()); });
    connect(m_stop, &StopButton::stopped, m_jog, &JogPad::releaseAll);
    connect(m_stop, &StopButton::stopped, station, [station] { station->endJog({}); });
    connect(m_stop, &StopButton::stopped, this, [this] { log(false, tr("Stop sent")); });
    connect(station, &RemoteStation::replied, this, [this](const QString &, const QString &command, bool ok, const QString &error) {
        if (command != u"jog" || !ok)
            log(!ok, ok ? tr("%1: accepted by the station").arg(command) : tr("%1 refused: %2").arg(command, error));
    });
    connect(station, &RemoteStation::commandFailed, this,
            [this](const QString &command, const QString &why) { log(true, tr("%1: %2").arg(command, why)); });
    connect(station, &RemoteStation::messageRefused, this, [this](const QString &what) { log(true, what); });
    connect(station, &RemoteStation::connectionChanged, this, [this](remote::MqttClient::State s, const QString &detail) {
        if (s == remote::MqttClient::State::Connected)
            log(false, tr("connected to %1").arg(m_station->brokerDisplay()));
        else if (s == remote::MqttClient::State::Reconnecting)
            log(true, tr("broker: %1").arg(detail));
    });
    connect(station, &RemoteStation::onlineChanged, this, [this](bool online) {
        log(!online, online ? tr("station %1 is online").arg(m_station->name())
                            : tr("station %1 went offline").arg(m_station->name()));
    });
    // Esc and Pause stop, wherever the focus is (a text field keeps Space).
    for (const Qt::Key key : {Qt::Key_Escape, Qt::Key_Pause}) {
        auto *stop = new QShortcut(QKeySequence(key), this);
        stop->setContext(Qt::WindowShortcut);
        connect(stop, &QShortcut::activated, m_stop,
                [this, key] { m_stop->stopFor(key == Qt::Key_Escape ? tr("the Esc key") : tr("the Pause key")); });
    }
    showLive(false);
    const QScreen *screen = QGuiApplication::primaryScreen();
    const QSize room = screen ? screen->availableSize() : QSize(1440, 900);
    resize(QSize(1440, 900).boundedTo(room));
}

void RemoteStationWindow::log(bool problem, const QString &text)
{
    m_log->addEvent(QDateTime::currentDateTime(), problem ? AlarmMonitor::Severity::Warning : AlarmMonitor::Severity::Info,
                    text);
    statusBar()->showMessage(text, problem ? 30000 : 8000);
}

void RemoteStationWindow::showPlan(const face::StationPlan &plan)
{
    // The pass ahead on the plot, as the local window's Tracking tab draws it.
    if (plan.target.isEmpty() || plan.sky.isEmpty()) {
        m_plot->setPassOverlay(std::nullopt);
        return;
    }
    PassOverlay overlay;
    overlay.sky = plan.sky;
    overlay.planned = plan.path;
    overlay.azimuthTurnStart = plan.azimuthTurnStart;
    overlay.azimuthTurnEnd = plan.azimuthTurnEnd;
    overlay.flipped = plan.flipped;
    overlay.overTheTop = plan.overTheTop;
    overlay.unwinds = plan.unwinds;
    m_plot->setPassOverlay(overlay);
}

void RemoteStationWindow::showState(const face::StationState &s)
{
    m_plot->setLimits(s.limits);
    m_plot->setPark(s.park);
    if (s.position)
        m_plot->setActual(s.position->x(), s.position->y(), s.stale || !m_station->isLive());
    if (s.target)
        m_plot->setTarget(s.target->x(), s.target->y());
    else
        m_plot->clearTarget();
    m_charts->setElevationShown(!s.azimuthOnly);
    m_alarms->showAlarms(s.alarms, s.severe);
    if (s.alarms != m_lastAlarms) {
        for (const QString &a : s.alarms) {
            if (!m_lastAlarms.contains(a))
                log(true, tr("alarm: %1").arg(a));
        }
        m_lastAlarms = s.alarms;
    }
}

void RemoteStationWindow::showLive(bool live)
{
    m_controls->setLive(live);
    m_jog->setEnabled(live);
    if (!live)
        m_jog->releaseAll();
    if (const auto &s = m_station->state(); s && s->position)
        m_plot->setActual(s->position->x(), s->position->y(), s->stale || !live);
    if (!live) {
        // What the station said last still shows, dimmed; the banner says why.
        QStringList alarms = m_station->state() ? m_station->state()->alarms : QStringList();
        alarms.prepend(tr("Not live: %1").arg(m_station->whyNotLive()));
        m_alarms->showAlarms(alarms, true);
    } else if (const auto &s = m_station->state()) {
        m_alarms->showAlarms(s->alarms, s->severe);
    }
}

} // namespace slew::ui
