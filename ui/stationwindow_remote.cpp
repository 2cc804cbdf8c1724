// SPDX-License-Identifier: GPL-3.0-or-later
// The station window's door for a station on a broker (stationwindow.h):
// what only a station seen from afar has. A banner across the top says it
// is remote, which station on which broker, and how old the last state is;
// the telemetry and the plan come from the broker; its Tracking tab has
// tracking by name and the station's published schedule until the local
// Tracking tab is on the face; the broker's and the station's words go to
// the event log.

#include "stationwindow.h"

#include "eventlog.h"
#include "radio/radiocontrol.h"
#include "remote/remotebanner.h"
#include "remote/remotecontrols.h"
#include "rotor/passoverlay.h"
#include "rotor/polarplotwidget.h"
#include "stopbutton.h"
#include "telemetry/telemetryrecorder.h"
#include "tracking/schedulepanel.h"
#include "widgets/titledgroup.h"

#include "remote/remotestation.h"

#include <QDateTime>
#include <QGuiApplication>
#include <QScreen>
#include <QStatusBar>
#include <QTabWidget>
#include <QVBoxLayout>

namespace slew::ui {

using remote::RemoteStation;

void StationWindow::openRemoteDoor()
{
    RemoteStation *station = m_remote;
    m_remoteBanner = new RemoteBanner(station);
    m_controls = new RemoteControls(station);
    // As the local window's Tracking tab: a target to track, and below it
    // the station's schedule.
    auto *tracking = new QWidget;
    tracking->setObjectName(QStringLiteral("remoteTrackingPage"));
    auto *trackingLayout = new QVBoxLayout(tracking);
    trackingLayout->addWidget(titledGroup(tr("One target"), m_controls));
    trackingLayout->addWidget(titledGroup(tr("Schedule"), m_schedule), 1);
    m_tabs->addTab(tracking, tr("Tracking"));
    // The radio as the station's face has it: its link, who has its dial,
    // where it is tuned, and the dial taken or handed back.
    auto *radio = new QWidget;
    radio->setObjectName(QStringLiteral("remoteRadioPage"));
    auto *radioGroup = new QWidget;
    auto *radioLayout = new QVBoxLayout(radioGroup);
    radioLayout->setContentsMargins(0, 0, 0, 0);
    radioLayout->addWidget(new RadioStateLine(station));
    auto *hold = new RadioControlButton(station);
    connect(hold, &RadioControlButton::message, this, [this](const QString &text) { remoteLog(true, text); });
    radioLayout->addWidget(hold, 0, Qt::AlignLeft);
    auto *radioPageLayout = new QVBoxLayout(radio);
    radioPageLayout->addWidget(titledGroup(tr("Radio"), radioGroup));
    radioPageLayout->addStretch(1);
    m_tabs->addTab(radio, tr("Radio"));
    layOut(m_remoteBanner, nullptr, nullptr);

    connect(station, &RemoteStation::telemetryReceived, m_recorder, &TelemetryRecorder::recordRemote);
    connect(station, &RemoteStation::liveChanged, m_controls, &RemoteControls::setLive);
    connect(station, &RemoteStation::planChanged, this, &StationWindow::showPlan);
    connect(station, &RemoteStation::stateChanged, this, [this](const face::StationState &s) { logNewAlarms(s.alarms); });
    connect(m_stop, &StopButton::stopped, station, [station] { station->endJog({}); });
    connect(m_stop, &StopButton::stopped, this, [this] { remoteLog(false, tr("Stop sent")); });
    connect(station, &RemoteStation::replied, this, [this](const QString &, const QString &command, bool ok, const QString &error) {
        // Jog renewals and previews are many and answered where they are
        // shown: only a refusal is worth a line.
        if ((command != u"jog" && command != u"schedule_preview") || !ok)
            remoteLog(!ok, ok ? tr("%1: accepted by the station").arg(command) : tr("%1 refused: %2").arg(command, error));
    });
    connect(station, &RemoteStation::commandFailed, this,
            [this](const QString &command, const QString &why) { remoteLog(true, tr("%1: %2").arg(command, why)); });
    connect(station, &RemoteStation::messageRefused, this, [this](const QString &what) { remoteLog(true, what); });
    connect(station, &RemoteStation::connectionChanged, this, [this](remote::MqttClient::State s, const QString &detail) {
        if (s == remote::MqttClient::State::Connected)
            remoteLog(false, tr("connected to %1").arg(m_remote->brokerDisplay()));
        else if (s == remote::MqttClient::State::Reconnecting)
            remoteLog(true, tr("broker: %1").arg(detail));
    });
    connect(station, &RemoteStation::onlineChanged, this, [this](bool online) {
        remoteLog(!online, online ? tr("station %1 is online").arg(m_remote->name())
                                  : tr("station %1 went offline").arg(m_remote->name()));
    });
    m_controls->setLive(station->isLive());
    showLive(station->isLive());
    const QScreen *screen = QGuiApplication::primaryScreen();
    const QSize room = screen ? screen->availableSize() : QSize(1440, 900);
    resize(QSize(1440, 900).boundedTo(room));
}

void StationWindow::remoteLog(bool problem, const QString &text)
{
    m_log->addEvent(QDateTime::currentDateTime(),
                    problem ? station::AlarmMonitor::Severity::Warning : station::AlarmMonitor::Severity::Info, text);
    statusBar()->showMessage(text, problem ? 30000 : 8000);
}

void StationWindow::logNewAlarms(const QStringList &alarms)
{
    if (alarms == m_lastAlarms)
        return;
    for (const QString &a : alarms) {
        if (!m_lastAlarms.contains(a))
            remoteLog(true, tr("alarm: %1").arg(a));
    }
    m_lastAlarms = alarms;
}

void StationWindow::showPlan(const face::StationPlan &plan)
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

} // namespace slew::ui
