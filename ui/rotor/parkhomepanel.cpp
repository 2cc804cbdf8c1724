// SPDX-License-Identifier: GPL-3.0-or-later
#include "rotor/parkhomepanel.h"

#include "operatortheme.h"
#include "protocol/dialect.h"

#include <QGridLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>

#include <cmath>

namespace slew::ui {

using session::RotatorSession;

ParkHomePanel::ParkHomePanel(RotatorSession *session, QWidget *parent) : QWidget(parent), m_session(session)
{
    setObjectName(QStringLiteral("parkHomePanel"));
    m_park = new QPushButton(tr("Park"));
    m_park->setObjectName(QStringLiteral("parkButton"));
    m_home = new QPushButton(tr("Home"));
    m_home->setObjectName(QStringLiteral("homeButton"));
    m_cancel = new QPushButton(tr("Cancel"));
    m_cancel->setObjectName(QStringLiteral("homeCancel"));
    m_cancel->setVisible(false);
    m_progress = new QProgressBar;
    m_progress->setObjectName(QStringLiteral("homeProgress"));
    m_progress->setRange(0, 0); // how long homing takes is unknown: a busy bar
    m_progress->setTextVisible(false);
    m_progress->setMaximumHeight(10);
    m_progress->setVisible(false);
    m_message = new QLabel;
    m_message->setObjectName(QStringLiteral("homeMessage"));
    m_message->setWordWrap(true);
    for (QPushButton *b : {m_park, m_home, m_cancel}) {
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

    m_timeout.setSingleShot(true);
    m_timeout.setInterval(kHomingTimeoutMs);
    connect(&m_timeout, &QTimer::timeout, this,
            [this] { finish(false, tr("Homing did not finish within %1 s.").arg(kHomingTimeoutMs / 1000)); });
    connect(m_park, &QPushButton::clicked, this, &ParkHomePanel::park);
    connect(m_home, &QPushButton::clicked, this, &ParkHomePanel::home);
    connect(m_cancel, &QPushButton::clicked, this, &ParkHomePanel::cancelHoming);
    connect(session, &RotatorSession::statusChanged, this, &ParkHomePanel::onStatus);
    connect(session, &RotatorSession::positionChanged, this, &ParkHomePanel::onPosition);
    connect(session, &RotatorSession::errorFlagsChanged, this, [this](int ge) {
        if (m_homing && ge > 1 && (ge & session::ErrorHoming))
            finish(false, tr("Homing failed: %1.").arg(session::describeErrorFlags(ge)));
    });
    connect(session, &RotatorSession::stateChanged, this, [this](RotatorSession::State s) {
        if (m_homing && s != RotatorSession::State::Connected)
            finish(false, tr("Homing interrupted: the link went down."));
        updateEnabled();
    });
    connect(session, &RotatorSession::capabilitiesChanged, this, &ParkHomePanel::updateEnabled);
    connect(session, &RotatorSession::profileChanged, this, &ParkHomePanel::updateEnabled);
    connect(session, &RotatorSession::parkChanged, this, &ParkHomePanel::updateEnabled); // the tooltip
    updateEnabled();
}

void ParkHomePanel::updateEnabled()
{
    const bool connected = m_session->isConnected();
    m_park->setEnabled(connected && !m_homing);
    const auto &caps = m_session->capabilities();
    // Without a park command the session parks by a go-to (RotatorSession::park).
    const bool parksByGoto = !protocol::dialectSupports(m_session->profile().dialect, protocol::Op::Park);
    m_park->setToolTip(parksByGoto ? tr("Move to the park position, by a go-to: this controller has no park command")
                                   : tr("Move to the park position (%1)").arg(parkText()));
    const bool noHoming = caps.probed && !caps.reset;
    m_home->setEnabled(connected && !m_homing && !noHoming);
    // A greyed-out Home says why, so it is not taken for a fault.
    m_home->setToolTip(noHoming ? tr("%1 has no homing command: this controller cannot find its end stops.")
                                      .arg(protocol::dialectName(m_session->profile().dialect))
                                : tr("Find the end stops and re-zero (RESET)"));
}

bool ParkHomePanel::park()
{
    const session::CommandResult sent = m_session->park();
    // PARK goes where the controller's registers say even before Slew has
    // read them; only the text waits for them.
    m_message->setText(sent ? m_session->parkKnown() ? tr("Parking at %1.").arg(parkText())
                                                     : tr("Parking where the controller says (%1).").arg(parkText())
                            : tr("Not parking: %1").arg(sent.refusal));
    m_message->setStyleSheet(sent ? QString() : refusedText());
    m_parking = bool(sent);
    if (sent)
        emit moveSent(tr("park (%1)").arg(parkText()),
                      m_session->parkKnown()
                          ? std::optional<QPointF>(QPointF(m_session->parkAzimuth(), m_session->parkElevation()))
                          : std::nullopt);
    return bool(sent);
}

QString ParkHomePanel::parkText() const
{
    // Where the antenna will point, as the plot's P shows it.
    if (!m_session->parkKnown())
        return tr("park not read yet");
    return tr("%1°, %2°").arg(m_session->parkAzimuth(), 0, 'f', 1).arg(m_session->parkElevation(), 0, 'f', 1);
}

bool ParkHomePanel::home()
{
    if (m_homing)
        return false;
    if (const session::CommandResult sent = m_session->home(); !sent) {
        m_message->setText(tr("Not homing: %1").arg(sent.refusal));
        m_message->setStyleSheet(refusedText());
        m_parking = false;
        return false;
    }
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

void ParkHomePanel::onStatus(session::StatusWord status)
{
    if (!m_homing || !status.valid)
        return;
    if (status.anyError()) {
        finish(false, tr("Homing failed: the controller reports an axis error."));
        return;
    }
    if (status.anyMoving())
        m_sawMoving = true;
    else if (m_sawMoving)
        finish(true, tr("Homed."));
}

void ParkHomePanel::onPosition(double az, double el, bool stale)
{
    if (!m_homing || stale || m_sawMoving)
        return;
    if (!m_hasStart) {
        m_hasStart = true;
        m_startAz = az;
        m_startEl = el;
        return;
    }
    // More than a reading's jitter: the rotator is on its way.
    constexpr double kMovedDeg = 0.2;
    if (std::abs(az - m_startAz) > kMovedDeg || std::abs(el - m_startEl) > kMovedDeg)
        m_sawMoving = true;
}

void ParkHomePanel::cancelHoming()
{
    if (!m_homing)
        return;
    m_session->stop(tr("homing was cancelled"));
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
