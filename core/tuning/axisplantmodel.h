#pragma once
// A second-order model of one axis as its controller drives it: a load with
// inertia J and viscous drag b, pushed by the controller's PID
//
//     J·x'' = kp·e + ki·∫e − kd·x' − b·x'
//
// with the derivative on the measured speed (the SatNOGS-style firmware and
// our simulator both do this, so a new target gives no kick). The gains are
// known (read with CR), so a recorded step pins down J and b; the proposal
// is then made for the model, not by rule of thumb.

#include "model/rotatorprofile.h"
#include "stepresponse.h"

#include <QList>

namespace slew::tuning {

struct AxisPlantModel {
    double inertia = 1.0;  // J, relative: the gains read as deg/s² per degree
    double drag = 0.0;     // b, deg/s² per deg/s

    // Positions at the given times (s after the step) for a step from
    // `start` to `target` under `gains`.
    QList<double> simulate(const model::PidGains &gains, double start, double target, const QList<double> &times) const;
};

struct PlantFit {
    AxisPlantModel model;
    double rmsError = 0.0; // degrees between the model and the samples
    bool ok = false;
    QString error;         // why there is no fit
};

// Least-squares fit of J and b to a recorded step (Nelder–Mead on their
// logarithms, since both are positive and may be off by orders of magnitude).
PlantFit fitAxisPlant(const StepResponse &step, const model::PidGains &gains);

} // namespace slew::tuning
