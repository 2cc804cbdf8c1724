// SPDX-License-Identifier: GPL-3.0-or-later
#include "axistuner.h"

#include "sampleclock.h"
#include "session/rotatorsession.h"

#include <cmath>

namespace slew::tuning {

using session::Axis;
using session::RotatorSession;

namespace {

constexpr double kLimitMargin = 1.0; // degrees kept clear of a limit by the step
constexpr double kRestingSlack = 0.1; // degrees past a limit that still count as resting on it

} // namespace

AxisTuner::AxisTuner(RotatorSession *session, QObject *parent)
    : QObject(parent), m_session(session), m_step(session), m_registers(session)
{
    qRegisterMetaType<TuningResult>();
    connect(&m_step, &StepExperiment::finished, this, &AxisTuner::onStepFinished);
    connect(&m_step, &StepExperiment::failed, this, &AxisTuner::onStepFailed);
    connect(&m_step, &StepExperiment::sampleRecorded, this,
            [this](const PositionSample &s) { emit sampleRecorded(m_phase == Phase::MeasuringAfter, s); });
    connect(&m_step, &StepExperiment::progress, this, [this](double fraction, const QString &what) {
        if (m_phase == Phase::MeasuringBefore)
            emit progress(5 + int(40 * fraction), tr("before: %1").arg(what));
        else if (m_phase == Phase::MeasuringAfter)
            emit progress(55 + int(40 * fraction), tr("after: %1").arg(what));
    });
    connect(&m_registers, &RegisterReadback::finished, this, [this](bool ok) {
        switch (m_phase) {
        case Phase::ReadingGains: onGainsRead(ok); break;
        case Phase::WritingTrial: onTrialWritten(ok); break;
        case Phase::Restoring: onRestored(ok); break;
        default: break;
        }
    });
}

bool AxisTuner::isRunning() const
{
    return m_phase != Phase::Idle && m_phase != Phase::Done && m_phase != Phase::Cancelled
        && m_phase != Phase::Failed;
}

void AxisTuner::setPhase(Phase p, int percent, const QString &what)
{
    m_phase = p;
    emit progress(percent, what);
}

bool AxisTuner::start(Axis axis)
{
    m_error.clear();
    if (isRunning()) {
        m_error = tr("tuning is already running");
        return false;
    }
    if (!m_session->isConnected() || !m_session->hasPosition()) {
        m_error = tr("connect to the rotator first: there is no position to measure");
        return false;
    }
    if (m_session->capabilities().probed && !m_session->capabilities().config) {
        m_error = tr("this controller does not answer CR: its gains cannot be read or written");
        return false;
    }
    if (!(m_settings.amplitude > 0.0) || !std::isfinite(m_settings.amplitude)) {
        m_error = tr("the step size must be a positive number of degrees");
        return false;
    }
    if (const QString why = fasterThanRealTime(m_session); !why.isEmpty()) {
        m_error = tr("not tuned: %1").arg(why);
        return false;
    }
    // The gate's travel: positions here are in the pointing frame, as its are.
    const model::RotatorLimits lim = m_session->moveGate().limits();
    const double lo = axis == Axis::Azimuth ? lim.azMin : lim.elMin;
    const double hi = axis == Axis::Azimuth ? lim.azMax : lim.elMax;
    double here = std::round((axis == Axis::Azimuth ? m_session->azimuth() : m_session->elevation()) * 100) / 100;
    // An axis resting at a limit may read a hundredth or two past it (just
    // homed, say, with the loop not yet pulled in against friction): that
    // is the limit, and the step starts from there.
    if (here < lo && here >= lo - kRestingSlack)
        here = lo;
    else if (here > hi && here <= hi + kRestingSlack)
        here = hi;
    const double a = m_settings.amplitude;
    if (here + a <= hi - kLimitMargin && here >= lo)
        m_to = here + a;
    else if (here - a >= lo + kLimitMargin && here <= hi)
        m_to = here - a;
    else {
        m_error = tr("a %1° step from %2° does not fit inside %3°..%4°").arg(a).arg(here).arg(lo).arg(hi);
        return false;
    }
    m_from = here;
    m_axis = axis;
    m_trialWritten = false;
    m_cancelReason.clear();
    m_result = TuningResult{};
    m_result.axis = axis;
    m_settings.step.band = StepResponseAnalyzer(m_settings.analysis).bandFor(a);
    m_step.setSettings(m_settings.step);

    const int first = firstGainRegister(axis);
    if (!m_registers.run({}, {first, first + 1, first + 2})) {
        m_error = m_registers.error();
        return false;
    }
    setPhase(Phase::ReadingGains, 0, tr("reading the %1 gains (CR%2..CR%3)").arg(axisName(axis)).arg(first).arg(first + 2));
    return true;
}

void AxisTuner::onGainsRead(bool ok)
{
    if (!m_cancelReason.isEmpty()) {
        m_phase = Phase::Cancelled;
        emit cancelled(m_cancelReason);
        return;
    }
    const int first = firstGainRegister(m_axis);
    const auto kp = m_registers.number(first), ki = m_registers.number(first + 1), kd = m_registers.number(first + 2);
    if (!ok || !kp || !ki || !kd) {
        fail(tr("the controller did not report its %1 gains (CR%2..CR%3)").arg(axisName(m_axis)).arg(first).arg(first + 2));
        return;
    }
    m_result.oldGains = model::PidGains{*kp, *ki, *kd};
    m_phase = Phase::MeasuringBefore;
    startStep();
}

void AxisTuner::startStep()
{
    if (!m_step.start(m_axis, m_from, m_to))
        fail(m_step.error());
}

void AxisTuner::onStepFinished(const StepResponse &response)
{
    // A rehearsal started while the step ran: its samples are too few to
    // go by, and nothing is offered from them (fail() writes the old gains
    // back if a trial is on the controller).
    if (const QString why = fasterThanRealTime(m_session); !why.isEmpty()) {
        fail(tr("the measurement is discarded: %1").arg(why));
        return;
    }
    const StepResponseAnalyzer analyzer(m_settings.analysis);
    if (m_phase == Phase::MeasuringBefore) {
        m_result.before = response;
        m_result.beforeMetrics = analyzer.analyze(response);
        m_result.motion = measureAxisMotion(response, m_settings.step.band);
        setPhase(Phase::Proposing, 50, tr("fitting a model to the step"));
        m_result.fit = fitAxisPlant(response, m_result.oldGains);
        if (!m_result.fit.ok) {
            fail(m_result.fit.error);
            return;
        }
        const GainProposal proposal = GainProposer(m_settings.proposal).propose(m_result.fit.model, m_result.oldGains);
        if (!proposal.ok) {
            fail(proposal.error);
            return;
        }
        m_result.newGains = proposal.gains;
        m_result.dampingBefore = GainProposer::dampingOf(m_result.fit.model, m_result.oldGains);
        m_result.dampingAfter = proposal.damping;
        // Registers change from here on: whatever happens next restores them.
        m_trialWritten = true;
        if (!writeGains(proposal.gains)) {
            fail(m_registers.error());
            return;
        }
        setPhase(Phase::WritingTrial, 52, tr("writing the proposed gains for a trial"));
    } else if (m_phase == Phase::MeasuringAfter) {
        m_result.after = response;
        m_result.afterMetrics = analyzer.analyze(response);
        setPhase(Phase::AwaitingDecision, 100, tr("done: accept the new gains, retry, or keep the old ones"));
        emit resultReady(m_result);
    }
}

void AxisTuner::onStepFailed(const QString &reason)
{
    fail(reason);
}

bool AxisTuner::writeGains(const model::PidGains &gains)
{
    const int first = firstGainRegister(m_axis);
    return m_registers.run({{first, RegisterReadback::format(gains.kp)},
                            {first + 1, RegisterReadback::format(gains.ki)},
                            {first + 2, RegisterReadback::format(gains.kd)}});
}

void AxisTuner::onTrialWritten(bool ok)
{
    if (!m_cancelReason.isEmpty()) {
        cancel();
        return;
    }
    if (!ok) {
        fail(tr("the controller did not take the proposed gains: %1")
                 .arg(m_registers.results().isEmpty() ? QString() : m_registers.results().front().describe()));
        return;
    }
    m_phase = Phase::MeasuringAfter;
    startStep();
}

void AxisTuner::accept()
{
    if (m_phase != Phase::AwaitingDecision)
        return;
    m_result.applied = true;
    m_trialWritten = false;
    setPhase(Phase::Done, 100, tr("new %1 gains kept on the controller").arg(axisName(m_axis)));
    emit finished(m_result);
}

void AxisTuner::keepOldGains()
{
    if (m_phase != Phase::AwaitingDecision)
        return;
    m_afterRestore = Phase::Done;
    if (!writeGains(m_result.oldGains)) {
        fail(m_registers.error());
        return;
    }
    setPhase(Phase::Restoring, 100, tr("writing the old %1 gains back").arg(axisName(m_axis)));
}

void AxisTuner::retry()
{
    if (m_phase != Phase::AwaitingDecision)
        return;
    m_afterRestore = Phase::Idle; // Idle here means "start again"
    if (!writeGains(m_result.oldGains)) {
        fail(m_registers.error());
        return;
    }
    setPhase(Phase::Restoring, 0, tr("writing the old %1 gains back before trying again").arg(axisName(m_axis)));
}

void AxisTuner::cancel()
{
    if (!isRunning())
        return;
    if (m_cancelReason.isEmpty())
        m_cancelReason = tr("tuning of %1 cancelled").arg(axisName(m_axis));
    m_step.cancel();
    m_session->stop(m_cancelReason, m_axis == Axis::Azimuth ? session::Axes::Azimuth : session::Axes::Elevation);
    if (m_phase == Phase::Restoring) {
        m_afterRestore = Phase::Cancelled;
        return;
    }
    if (m_registers.isRunning())
        return; // its finished() comes back here once the controller has answered
    if (m_trialWritten) {
        m_afterRestore = Phase::Cancelled;
        if (writeGains(m_result.oldGains)) {
            setPhase(Phase::Restoring, 100, tr("cancelled: writing the old %1 gains back").arg(axisName(m_axis)));
            return;
        }
    }
    m_phase = Phase::Cancelled;
    emit cancelled(m_cancelReason);
}

void AxisTuner::onRestored(bool ok)
{
    m_trialWritten = !ok;
    const QString note = ok ? QString()
                            : tr(" (the old gains could not be confirmed: %1)")
                                  .arg(m_registers.results().isEmpty() ? QString()
                                                                       : m_registers.results().front().describe());
    switch (m_afterRestore) {
    case Phase::Cancelled:
        m_phase = Phase::Cancelled;
        emit cancelled(m_cancelReason + note);
        return;
    case Phase::Failed:
        m_phase = Phase::Failed;
        emit failed(m_error + note);
        return;
    case Phase::Idle:
        m_phase = Phase::Idle;
        if (!ok) {
            m_phase = Phase::Failed;
            emit failed(tr("retry: the old gains could not be restored") + note);
        } else if (!start(m_axis)) {
            m_phase = Phase::Failed;
            emit failed(m_error);
        }
        return;
    default:
        m_result.applied = false;
        setPhase(Phase::Done, 100, tr("old %1 gains kept").arg(axisName(m_axis)) + note);
        emit finished(m_result);
        return;
    }
}

void AxisTuner::fail(const QString &reason)
{
    m_error = reason;
    m_step.cancel();
    m_session->stop(tr("tuning of %1 failed: %2").arg(axisName(m_axis), reason),
                    m_axis == Axis::Azimuth ? session::Axes::Azimuth : session::Axes::Elevation);
    if (m_trialWritten && !m_registers.isRunning()) {
        m_afterRestore = Phase::Failed;
        if (writeGains(m_result.oldGains)) {
            m_phase = Phase::Restoring;
            return;
        }
    }
    m_phase = Phase::Failed;
    emit failed(reason);
}

} // namespace slew::tuning
