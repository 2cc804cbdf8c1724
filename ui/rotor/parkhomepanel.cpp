// SPDX-License-Identifier: GPL-3.0-or-later
#include "rotor/parkhomepanel.h"

#include "operatortheme.h"

#include <QGridLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>

#include <cmath>

namespace slew::ui {

ParkHomePanel::ParkHomePanel(face::StationFace *station, QWidget *parent) : QWidget(parent), m_station(station)
{
    setObjectName(QStringLiteral("parkHomePanel"));
    m_park = new QPushButton(tr("Park"));
    m_park->setObjectName(QStringLiteral("parkButton"));
    m_home = new QPushButton(tr("Home"));
    m_home->setObjectName(QStringLiteral("homeButton"));
    m_cancel = new QPushButton(tr("Cancel"));
    m_cancel->setObjectName(QStringLiteral("homeCancel"));
    m_cancel->setVisible(false);
    // Shown while the motion guard holds an axis: the operator has looked.
    m_clearFault = new QPushButton(tr("Clear motion fault"));
    m_clearFault->setObjectName(QStringLiteral("clearMotionFault"));
    m_clearFault->setToolTip(tr("The motion guard stopped an axis that did not move, or ran the wrong way, and holds "
                                "it: clear it once the rotator has been looked at, to drive it again"));
    m_clearFault->setVisible(false);
    m_progress = new QProgressBar;
    m_progress->setObjectName(QStringLiteral("homeProgress"));
    m_progress->setRange(0, 0); // how long homing takes is unknown: a busy bar
    m_progress->setTextVisible(false);
    m_progress->setMaximumHeight(10);
    m_progress->setVisible(false);
    m_message = new QLabel;
    m_message->setObjectName(QStringLiteral("homeMessage"));
    m_message->setWordWrap(true);
    for (QPushButton *b : {m_park, m_home, m_cancel, m_clearFault}) {
        b->setAutoDefault(false);
        b->setFocusPolicy(Qt::NoFocus);
    }

    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->addWidget(m_park, 0, 0);
    grid->addWidget(m_home, 0, 1);
    grid->addWidget(m_cancel, 0, 2);
    grid->addWidget(m_progress, 1, 0, 1, 3);
    grid->addWidget(m_message, 2, 0, 1, 3);
    // In Home's place, which a held axis refuses anyway: no taller column.
    grid->addWidget(m_clearFault, 0, 1, 1, 2);

    m_timeout.setSingleShot(true);
    m_timeout.setInterval(kHomingTimeoutMs);
    connect(&m_timeout, &QTimer::timeout, this,
            [this] { finish(false, tr("Homing did not finish within %1 s.").arg(kHomingTimeoutMs / 1000)); });
    connect(m_park, &QPushButton::clicked, this, &ParkHomePanel::park);
    connect(m_home, &QPushButton::clicked, this, &ParkHomePanel::home);
    connect(m_cancel, &QPushButton::clicked, this, &ParkHomePanel::cancelHoming);
    connect(m_clearFault, &QPushButton::clicked, this, [this] {
        const face::Outcome cleared = m_station->clearMotionFaults();
        if (cleared.isRefused())
            refused(tr("Not cleared"), cleared.reason());
        m_awaiting = cleared.id();
        m_awaitingWhat = tr("Not cleared");
    });
    connect(station, &face::StationFace::stateChanged, this, &ParkHomePanel::follow);
    connect(station, &face::StationFace::liveChanged, this, &ParkHomePanel::updateEnabled);
    connect(station, &face::StationFace::answered, this, [this](const QString &id, const face::Outcome &outcome) {
        if (id != m_awaiting)
            return;
        m_awaiting.clear();
        if (outcome.isRefused())
            refused(m_awaitingWhat, outcome.reason());
    });
    follow(station->state().value_or(face::StationState{}));
}

void ParkHomePanel::follow(const face::StationState &state)
{
    // A new status (GS) reading, not only a new position.
    const bool statusChanged = state.azimuthStatus != m_state.azimuthStatus
                               || state.elevationStatus != m_state.elevationStatus || state.moving != m_state.moving
                               || state.axisError != m_state.axisError;
    // The error register says so now, not from an earlier homing.
    const bool homingFailedNow = state.homingFailed && !m_state.homingFailed;
    m_state = state;
    if (m_homing && state.link != u"connected")
        finish(false, tr("Homing interrupted: the link went down."));
    followHoming(state, statusChanged, homingFailedNow);
    m_clearFault->setVisible(state.motionHeld);
    m_home->setVisible(!state.motionHeld);
    updateEnabled();
}

void ParkHomePanel::updateEnabled()
{
    const bool connected = m_state.link == u"connected" && m_station->isLive();
    m_park->setEnabled(connected && !m_homing);
    // Without a park command the session parks by a go-to (RotatorSession::park).
    const bool parksByGoto = !m_state.parkCommand;
    m_park->setToolTip(parksByGoto ? tr("Move to the park position, by a go-to: this controller has no park command")
                                   : tr("Move to the park position (%1)").arg(parkText()));
    const bool noHoming = !m_state.canHome;
    m_home->setEnabled(connected && !m_homing && !noHoming);
    // A greyed-out Home says why, so it is not taken for a fault.
    m_home->setToolTip(noHoming ? tr("%1 has no homing command: this controller cannot find its end stops.")
                                      .arg(m_state.dialect)
                                : tr("Find the end stops and re-zero (RESET)"));
}

bool ParkHomePanel::park()
{
    const face::Outcome sent = m_station->park();
    if (sent.isRefused()) {
        refused(tr("Not parking"), sent.reason());
        return false;
    }
    m_awaiting = sent.id();
    m_awaitingWhat = tr("Not parking");
    // PARK goes where the controller's registers say even before Slew has
    // read them; only the text waits for them.
    m_message->setText(m_state.park ? tr("Parking at %1.").arg(parkText())
                                    : tr("Parking where the controller says (%1).").arg(parkText()));
    m_message->setStyleSheet(QString());
    m_parking = true;
    emit moveSent(tr("park (%1)").arg(parkText()), m_state.park);
    return true;
}

void ParkHomePanel::refused(const QString &what, const QString &why)
{
    if (m_homing)
        finish(false, tr("%1: %2").arg(what, why));
    m_message->setText(tr("%1: %2").arg(what, why));
    m_message->setStyleSheet(refusedText());
    m_parking = false;
}

QString ParkHomePanel::parkText() const
{
    // Where the antenna will point, as the plot's P shows it.
    if (!m_state.park)
        return tr("park not read yet");
    return tr("%1°, %2°").arg(m_state.park->x(), 0, 'f', 1).arg(m_state.park->y(), 0, 'f', 1);
}

bool ParkHomePanel::home()
{
    if (m_homing)
        return false;
    const face::Outcome sent = m_station->home();
    if (sent.isRefused()) {
        refused(tr("Not homing"), sent.reason());
        return false;
    }
    m_awaiting = sent.id();
    m_awaitingWhat = tr("Not homing");
    m_homing = true;
    m_sawMoving = false;
    m_hasStart = false;
    m_timeout.start();
    m_progress->setVisible(true);
    m_cancel->setVisible(true);
    m_parking = false;
    m_message->setText(tr("Homing: looking for the end stops…"));
    m_message->setStyleSheet(QString());
    emit homingStarted();
    updateEnabled();
    return true;
}

void ParkHomePanel::moveEnded()
{
    if (m_parking)
        m_message->clear();
    m_parking = false;
}

void ParkHomePanel::followHoming(const face::StationState &state, bool statusChanged, bool homingFailed)
{
    if (!m_homing)
        return;
    if (homingFailed) {
        finish(false, tr("Homing failed: %1.").arg(state.controllerErrors));
        return;
    }
    if (statusChanged && state.axisError) {
        finish(false, tr("Homing failed: the controller reports an axis error."));
        return;
    }
    if (statusChanged && state.azimuthStatus) {
        if (state.moving) {
            m_sawMoving = true;
        } else if (m_sawMoving) { // GS says both axes are idle again
            finish(true, tr("Homed."));
            return;
        }
    }
    if (m_sawMoving || state.stale || !state.position)
        return;
    if (!m_hasStart) {
        m_hasStart = true;
        m_startAz = state.position->x();
        m_startEl = state.position->y();
        return;
    }
    // More than a reading's jitter: the rotator is on its way.
    constexpr double kMovedDeg = 0.2;
    if (std::abs(state.position->x() - m_startAz) > kMovedDeg || std::abs(state.position->y() - m_startEl) > kMovedDeg)
        m_sawMoving = true;
}

void ParkHomePanel::cancelHoming()
{
    if (!m_homing)
        return;
    m_station->stop(tr("homing was cancelled"));
    finish(false, tr("Homing cancelled; the rotator was stopped."));
}

void ParkHomePanel::abandonHoming()
{
    if (m_homing)
        finish(false, tr("Homing stopped."));
}

void ParkHomePanel::finish(bool ok, const QString &message)
{
    if (!m_homing)
        return;
    m_homing = false;
    m_timeout.stop();
    m_progress->setVisible(false);
    m_cancel->setVisible(false);
    m_message->setText(message);
    m_message->setStyleSheet(ok ? QString() : refusedText());
    updateEnabled();
    emit homingFinished(ok, message);
}

} // namespace slew::ui
