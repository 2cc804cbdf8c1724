#include "gainproposer.h"

#include <QObject>

#include <algorithm>
#include <cmath>

namespace slew::tuning {

namespace {

// Three significant figures: what an operator can read back and retype.
double rounded(double v)
{
    if (v <= 0.0)
        return 0.0;
    const double magnitude = std::pow(10.0, std::floor(std::log10(v)) - 2.0);
    return std::round(v / magnitude) * magnitude;
}

} // namespace

double GainProposer::naturalFrequencyOf(const AxisPlantModel &plant, const model::PidGains &gains)
{
    return plant.inertia > 0.0 && gains.kp > 0.0 ? std::sqrt(gains.kp / plant.inertia) : 0.0;
}

double GainProposer::dampingOf(const AxisPlantModel &plant, const model::PidGains &gains)
{
    const double wn = naturalFrequencyOf(plant, gains);
    return wn > 0.0 ? (plant.drag + gains.kd) / (2.0 * plant.inertia * wn) : 0.0;
}

GainProposal GainProposer::propose(const AxisPlantModel &plant, const model::PidGains &current) const
{
    GainProposal p;
    const double wnNow = naturalFrequencyOf(plant, current);
    if (wnNow <= 0.0 || !std::isfinite(wnNow)) {
        p.error = QObject::tr("the model has no natural frequency (proportional gain %1, inertia %2)")
                      .arg(current.kp)
                      .arg(plant.inertia);
        return p;
    }
    const double wn = wnNow * m_settings.speedFactor;
    const double J = plant.inertia;
    model::PidGains g;
    g.kp = rounded(J * wn * wn);
    // The drag already damps the loop; the derivative supplies the rest.
    g.kd = rounded(std::max(0.0, 2.0 * m_settings.damping * wn * J - plant.drag));
    g.ki = current.ki > 0.0 || m_settings.integralRatio > 0.0 ? rounded(g.kp * wn * m_settings.integralRatio) : 0.0;
    if (g.kp > m_settings.maxGain || g.kd > m_settings.maxGain || g.ki > m_settings.maxGain) {
        p.error = QObject::tr("the proposed gains (kp %1, ki %2, kd %3) exceed what the controller accepts (%4)")
                      .arg(g.kp)
                      .arg(g.ki)
                      .arg(g.kd)
                      .arg(m_settings.maxGain);
        return p;
    }
    p.gains = g;
    p.naturalFrequency = wn;
    p.damping = dampingOf(plant, g);
    p.ok = true;
    return p;
}

} // namespace slew::tuning
