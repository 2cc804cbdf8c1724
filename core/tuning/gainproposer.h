#pragma once
// Gains from a fitted model by pole placement. The fitted model's closed
// loop is J·s² + (b + kd)·s + kp; the proposal keeps the natural frequency
// the axis already has (the recorded step proved the drive can follow it
// without running into its limits) and sets the damping to the target, which
// is what removes the overshoot and the ringing that makes settling slow.
// A small integral, a decade below the loop's frequency, takes out the
// offset friction leaves without bringing the overshoot back.

#include "axisplantmodel.h"

#include "model/rotatorprofile.h"

namespace slew::tuning {

struct ProposalSettings {
    double damping = 1.0;        // ζ: 1 is the fastest response with no overshoot
    double speedFactor = 1.0;    // natural frequency relative to the axis' present one
    double integralRatio = 0.1;  // integral zero at this share of the natural frequency
    double maxGain = 10000.0;    // what a CW register accepts (SatNOGS firmware, our simulator)
};

struct GainProposal {
    model::PidGains gains;
    double naturalFrequency = 0.0; // rad/s of the proposed loop
    double damping = 0.0;
    bool ok = false;
    QString error;
};

class GainProposer {
public:
    explicit GainProposer(const ProposalSettings &settings = {}) : m_settings(settings) {}

    GainProposal propose(const AxisPlantModel &plant, const model::PidGains &current) const;

    // The damping and natural frequency a model has under some gains, to
    // explain a before/after in words ("ζ 0.16 → 1.00").
    static double dampingOf(const AxisPlantModel &plant, const model::PidGains &gains);
    static double naturalFrequencyOf(const AxisPlantModel &plant, const model::PidGains &gains);

private:
    ProposalSettings m_settings;
};

} // namespace slew::tuning
