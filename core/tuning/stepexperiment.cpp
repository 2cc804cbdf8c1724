#include "stepexperiment.h"

#include "session/rotatorsession.h"

#include "model/movegate.h"

#include <algorithm>
#include <cmath>

namespace slew::tuning {

using session::Axis;
using session::RotatorSession;

StepExperiment::StepExperiment(RotatorSession *session, QObject *parent)
    : QObject(parent), m_session(session), m_clock(session)
{
    qRegisterMetaType<PositionSample>();
    qRegisterMetaType<StepResponse>();
    m_tick.setInterval(20);
    connect(&m_tick, &QTimer::timeout, this, &StepExperiment::evaluate);
    connect(m_session, &RotatorSession::positionChanged, this, &StepExperiment::onPosition);
}

double StepExperiment::reading() const
{
    return m_axis == Axis::Azimuth ? m_session->azimuth() : m_session->elevation();
}

bool StepExperiment::start(Axis axis, double from, double to)
{
    m_error.clear();
    if (m_phase == Phase::Preparing || m_phase == Phase::Stepping) {
        m_error = tr("a step is already running");
        return false;
    }
    if (!m_session->isConnected() || !m_session->hasPosition()) {
        m_error = tr("no position from the rotator yet");
        return false;
    }
    if (!std::isfinite(from) || !std::isfinite(to) || std::fabs(to - from) < 2 * m_settings.band) {
        m_error = tr("the step from %1° to %2° is too small to measure").arg(from).arg(to);
        return false;
    }
    // The ends as the controller will take them: a SPID controller at 2
    // pulses a degree, or GS-232's whole degrees, cannot be sent to 16.6°,
    // and would never be found resting "at" it.
    const double step = m_session->setResolutionDeg();
    if (step > 0) {
        from = std::round(from / step) * step;
        to = std::round(to / step) * step;
    }
    m_axis = axis;
    m_from = from;
    m_to = to;
    m_response = StepResponse{};
    // The far end is put to the session's gate before the first byte goes
    // out; the near end is sent, and so passes the gate, just below.
    const model::MoveGate &gate = m_session->moveGate();
    if (const model::MoveCheck far = axis == Axis::Azimuth ? gate.azimuthPosition(to) : gate.elevation(to);
        !far.allowed()) {
        m_error = far.refusal;
        return false;
    }
    if (const session::CommandResult sent = command(from); !sent) {
        m_error = sent.refusal;
        return false;
    }
    m_phase = Phase::Preparing;
    m_phaseStart = m_clock.now();
    m_last = reading();
    m_lastAway = std::fabs(m_last - from) > m_settings.band ? m_phaseStart : m_phaseStart - m_settings.holdSeconds / 2;
    m_lastSampleWall.start();
    m_tick.start();
    emit progress(0.0, tr("moving to the start, %1°").arg(from, 0, 'f', 2));
    return true;
}

session::CommandResult StepExperiment::command(double position)
{
    // Only the stepped axis is commanded where the dialect can (a set-position
    // for both would make the session take the other axis' unchanged reading
    // for an echo of the command). The position is mechanical: a step near
    // the overlap must not be turned into the same bearing elsewhere.
    return m_session->gotoAxis(m_axis, position, RotatorSession::AzimuthIs::Position);
}

void StepExperiment::onPosition(double az, double el, bool stale)
{
    if (stale || (m_phase != Phase::Preparing && m_phase != Phase::Stepping))
        return;
    m_lastSampleWall.restart();
    const double now = m_clock.now();
    m_last = m_axis == Axis::Azimuth ? az : el;
    const double goal = m_phase == Phase::Preparing ? m_from : m_to;
    if (std::fabs(m_last - goal) > m_settings.band)
        m_lastAway = now;
    if (m_phase == Phase::Stepping) {
        const PositionSample s{now - m_phaseStart, m_last};
        m_response.samples.append(s);
        emit sampleRecorded(s);
    }
    evaluate();
}

void StepExperiment::evaluate()
{
    if (m_phase != Phase::Preparing && m_phase != Phase::Stepping)
        return;
    if (m_lastSampleWall.elapsed() > m_settings.silenceMs) {
        fail(tr("no position from the rotator for %1 s").arg(m_settings.silenceMs / 1000.0));
        return;
    }
    const double now = m_clock.now();
    const double elapsed = now - m_phaseStart;
    const bool resting = now - m_lastAway >= m_settings.holdSeconds;
    if (m_phase == Phase::Preparing) {
        if (resting) {
            beginStep();
        } else if (elapsed > m_settings.prepareSeconds) {
            fail(tr("the axis did not come to rest at %1° within %2 s").arg(m_from).arg(m_settings.prepareSeconds));
        }
        return;
    }
    emit progress(std::min(1.0, elapsed / m_settings.maximumSeconds),
                  tr("step to %1°: %2 s").arg(m_to, 0, 'f', 2).arg(elapsed, 0, 'f', 1));
    if ((resting && elapsed >= m_settings.minimumSeconds) || elapsed >= m_settings.maximumSeconds)
        end();
}

void StepExperiment::beginStep()
{
    m_response.start = reading();
    m_response.target = m_to;
    if (const session::CommandResult sent = command(m_to); !sent) {
        fail(tr("the rotator refused the step to %1°: %2").arg(m_to).arg(sent.refusal));
        return;
    }
    m_phase = Phase::Stepping;
    m_phaseStart = m_clock.now();
    m_lastAway = m_phaseStart;
    emit progress(0.0, tr("step to %1°").arg(m_to, 0, 'f', 2));
}

void StepExperiment::end()
{
    m_tick.stop();
    m_phase = Phase::Done;
    m_response.duration = m_clock.now() - m_phaseStart;
    // Between samples the axis held its last value; close the record with
    // that value at the end so the flat tail counts.
    if (!m_response.samples.isEmpty() && m_response.samples.back().t < m_response.duration)
        m_response.samples.append(PositionSample{m_response.duration, m_last});
    emit progress(1.0, tr("step recorded"));
    emit finished(m_response);
}

void StepExperiment::fail(const QString &reason)
{
    m_tick.stop();
    m_phase = Phase::Done;
    m_error = reason;
    m_session->stop(tr("a tuning step failed: %1").arg(reason),
                    m_axis == Axis::Azimuth ? session::Axes::Azimuth : session::Axes::Elevation);
    emit failed(reason);
}

void StepExperiment::cancel()
{
    if (m_phase != Phase::Preparing && m_phase != Phase::Stepping)
        return;
    m_tick.stop();
    m_phase = Phase::Idle;
    m_session->stop(tr("a tuning step was cancelled"),
                    m_axis == Axis::Azimuth ? session::Axes::Azimuth : session::Axes::Elevation);
}

} // namespace slew::tuning
