#include "homingrun.h"

#include "session/rotatorsession.h"

#include <algorithm>
#include <cmath>

namespace slew::tuning {

using session::RotatorSession;

namespace {

constexpr double kHomeTolerance = 0.5; // degrees from the lower limit counts as home
constexpr double kHoldSeconds = 0.5;   // at home and still this long: done
constexpr double kMinimumSeconds = 1.0; // an axis already at zero still gets time to run RESET
constexpr int kTrustStaleErrorsMs = 3000; // a GE value older than RESET is believed after this long

} // namespace

HomingRun::HomingRun(RotatorSession *session, QObject *parent) : QObject(parent), m_session(session), m_clock(session)
{
    m_tick.setInterval(50);
    connect(&m_tick, &QTimer::timeout, this, &HomingRun::evaluate);
    connect(m_session, &RotatorSession::errorFlagsChanged, this, [this] {
        m_freshErrors = true;
        evaluate();
    });
    connect(m_session, &RotatorSession::positionChanged, this, &HomingRun::evaluate);
    connect(m_session, &RotatorSession::statusChanged, this, &HomingRun::evaluate);
    // A controller without RESET (K3NG's Easycom answers `?`) never starts:
    // said at once, not after the whole time limit.
    connect(m_session, &RotatorSession::controllerRefusedMove, this, [this](const QString &why) {
        if (!m_running)
            return;
        m_refusedByController = true;
        end(false, why);
    });
}

double HomingRun::distanceLeft() const
{
    // Homing ends at the lower limits, which the readings (pointing frame) see
    // shifted by the calibration offsets, as the gate does.
    const model::RotatorLimits lim = m_session->moveGate().limits();
    return std::fabs(m_session->azimuth() - lim.azMin) + std::fabs(m_session->elevation() - lim.elMin);
}

bool HomingRun::start(double timeoutSeconds)
{
    m_error.clear();
    if (m_running) {
        m_error = tr("homing is already running");
        return false;
    }
    if (!(timeoutSeconds > 0.0)) {
        m_error = tr("the homing time limit must be positive");
        return false;
    }
    if (const auto sent = m_session->home(); !sent) {
        m_error = sent.refusal;
        return false;
    }
    m_running = true;
    m_refusedByController = false;
    m_freshErrors = false;
    m_timeout = timeoutSeconds;
    m_started = m_clock.now();
    m_atHomeSince = -1.0;
    m_initialDistance = m_session->hasPosition() ? std::max(1.0, distanceLeft()) : 1.0;
    m_wall.start();
    m_tick.start();
    emit progress(0, tr("homing: RESET sent, looking for the end stops"));
    return true;
}

void HomingRun::evaluate()
{
    if (!m_running)
        return;
    const double now = m_clock.now();
    const double elapsed = now - m_started;

    const int ge = m_session->errorFlags();
    const bool believe = m_freshErrors || m_wall.elapsed() > kTrustStaleErrorsMs;
    if (believe && ge > 1) {
        const QString what = session::describeErrorFlags(ge);
        QString advice;
        if (ge & session::ErrorHoming)
            advice = tr(" An end stop did not trip: check the limit switch and its wiring.");
        else if (ge & session::ErrorMotor)
            advice = tr(" A motor stalled or is jammed.");
        end(false, tr("homing failed: the controller reports %1 (GE %2).").arg(what).arg(ge) + advice);
        return;
    }

    if (m_session->hasPosition()) {
        const double left = distanceLeft();
        const int percent = int(100.0 * std::clamp(1.0 - left / m_initialDistance, 0.0, 0.99));
        emit progress(percent, tr("homing: %1° to go, %2 s").arg(left, 0, 'f', 1).arg(elapsed, 0, 'f', 1));
        const bool still = !m_session->status().valid || !m_session->status().anyMoving();
        if (left <= 2 * kHomeTolerance && still && elapsed >= kMinimumSeconds) {
            if (m_atHomeSince < 0)
                m_atHomeSince = now;
            if (now - m_atHomeSince >= kHoldSeconds) {
                end(true, {});
                return;
            }
        } else {
            m_atHomeSince = -1.0;
        }
    }
    if (elapsed > m_timeout)
        end(false, tr("homing did not finish within %1 s; the rotator was stopped").arg(m_timeout));
}

void HomingRun::end(bool ok, const QString &reason)
{
    m_running = false;
    m_tick.stop();
    if (ok) {
        emit progress(100, tr("homed"));
        emit succeeded();
        return;
    }
    m_session->stop(tr("homing failed: %1").arg(reason));
    m_error = reason;
    emit failed(reason);
}

void HomingRun::cancel()
{
    if (!m_running)
        return;
    m_running = false;
    m_tick.stop();
    m_session->stop(tr("homing was cancelled"));
    m_error = tr("homing cancelled; the rotator was stopped");
    emit cancelled();
}

} // namespace slew::tuning
