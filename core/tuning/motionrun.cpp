// SPDX-License-Identifier: GPL-3.0-or-later
#include "motionrun.h"

#include "sampleclock.h"
#include "session/rotatorsession.h"

#include <cmath>

namespace slew::tuning {

using session::Axis;

namespace {
constexpr double kLimitMarginDeg = 1.0;
}

MotionRun::MotionRun(session::RotatorSession *session, QObject *parent)
    : QObject(parent), m_session(session), m_step(session)
{
    StepSettings settings;
    settings.band = 0.08;
    // 30° at a slow elevation's 2.7°/s, with room to brake and settle.
    settings.maximumSeconds = 40.0;
    settings.prepareSeconds = 5.0;
    m_step.setSettings(settings);
    connect(&m_step, &StepExperiment::finished, this, [this](const StepResponse &response) {
        // As in the tuner: a step measured faster than real time is not kept.
        if (const QString why = fasterThanRealTime(m_session); !why.isEmpty()) {
            emit failed(why);
            return;
        }
        const AxisMotion motion = measureAxisMotion(response, m_step.settings().band);
        if (motion.ok)
            emit measured(m_axis, motion);
        else
            emit failed(motion.error);
    });
    connect(&m_step, &StepExperiment::failed, this, &MotionRun::failed);
}

bool MotionRun::start(Axis axis)
{
    m_error.clear();
    if (isRunning()) {
        m_error = tr("the axis is already being measured");
        return false;
    }
    if (!m_session->isConnected() || !m_session->hasPosition()) {
        m_error = tr("connect to the rotator first: there is no position to measure from");
        return false;
    }
    if (const QString why = fasterThanRealTime(m_session); !why.isEmpty()) {
        m_error = tr("speed not measured: %1").arg(why);
        return false;
    }
    const model::RotatorLimits lim = m_session->moveGate().limits();
    const bool az = axis == Axis::Azimuth;
    const double lo = az ? lim.azMin : lim.elMin, hi = az ? lim.azMax : lim.elMax;
    const double here = std::round((az ? m_session->azimuth() : m_session->elevation()) * 100) / 100;
    double to = 0;
    if (here + kMotionStepDeg <= hi - kLimitMarginDeg)
        to = here + kMotionStepDeg;
    else if (here - kMotionStepDeg >= lo + kLimitMarginDeg)
        to = here - kMotionStepDeg;
    else {
        m_error = tr("a %1° move from %2° does not fit inside %3°..%4°").arg(kMotionStepDeg).arg(here).arg(lo).arg(hi);
        return false;
    }
    m_axis = axis;
    if (!m_step.start(axis, here, to)) {
        m_error = m_step.error();
        return false;
    }
    return true;
}

void MotionRun::cancel()
{
    if (isRunning())
        m_step.cancel();
}

} // namespace slew::tuning
