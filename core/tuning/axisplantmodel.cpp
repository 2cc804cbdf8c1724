#include "axisplantmodel.h"

#include <QObject>

#include <algorithm>
#include <array>
#include <cmath>

namespace slew::tuning {

namespace {

constexpr double kStep = 0.001;       // s, the model's integration step
constexpr double kMinDrag = 1e-3;     // the search works on log(b); b may be nearly zero
constexpr int kMaxEvaluations = 400;

} // namespace

QList<double> AxisPlantModel::simulate(const model::PidGains &gains, double start, double target,
                                       const QList<double> &times) const
{
    QList<double> out;
    out.reserve(times.size());
    double x = start;
    double v = 0.0;
    double integral = 0.0;
    double t = 0.0;
    for (double until : times) {
        while (t + kStep / 2 < until) {
            const double e = target - x;
            integral += e * kStep;
            const double u = gains.kp * e + gains.ki * integral - gains.kd * v;
            const double a = (u - drag * v) / inertia;
            v += a * kStep; // semi-implicit Euler: stable for the stiff gains a tuner meets
            x += v * kStep;
            t += kStep;
            if (!std::isfinite(x))
                x = v = 1e9; // a diverging candidate: give it a huge cost, not a NaN
        }
        out.append(x);
    }
    return out;
}

PlantFit fitAxisPlant(const StepResponse &step, const model::PidGains &gains)
{
    PlantFit fit;
    if (step.samples.size() < 5) {
        fit.error = QObject::tr("too few position samples (%1) to fit a model").arg(step.samples.size());
        return fit;
    }
    if (gains.kp <= 0.0) {
        fit.error = QObject::tr("the proportional gain is zero: the axis holds no position to measure");
        return fit;
    }
    if (std::fabs(step.amplitude()) < 1e-6) {
        fit.error = QObject::tr("the step has no size");
        return fit;
    }

    QList<double> times;
    times.reserve(step.samples.size());
    for (const PositionSample &s : step.samples)
        times.append(s.t);
    const double scale = 1.0 / (step.amplitude() * step.amplitude());

    using Point = std::array<double, 2>; // ln J, ln b
    auto cost = [&](const Point &p) {
        const AxisPlantModel m{std::exp(p[0]), std::exp(p[1])};
        const QList<double> y = m.simulate(gains, step.start, step.target, times);
        double sum = 0.0;
        for (qsizetype i = 0; i < y.size(); ++i) {
            const double d = y[i] - step.samples[i].position;
            sum += d * d;
        }
        return sum * scale / double(y.size());
    };

    // Start from a coarse grid so the simplex begins in the right valley.
    Point best{0.0, 0.0};
    double bestCost = std::numeric_limits<double>::infinity();
    for (double lj = -4.0; lj <= 4.0; lj += 1.0) {
        for (double lb = std::log(kMinDrag); lb <= 5.0; lb += 1.0) {
            const double c = cost({lj, lb});
            if (c < bestCost) {
                bestCost = c;
                best = {lj, lb};
            }
        }
    }

    // Nelder–Mead: reflect, expand, contract, shrink.
    std::array<Point, 3> simplex{best, Point{best[0] + 0.5, best[1]}, Point{best[0], best[1] + 0.5}};
    std::array<double, 3> costs{bestCost, cost(simplex[1]), cost(simplex[2])};
    int evaluations = 2;
    while (evaluations < kMaxEvaluations) {
        std::array<int, 3> order{0, 1, 2};
        std::sort(order.begin(), order.end(), [&](int a, int b) { return costs[a] < costs[b]; });
        const int lo = order[0], mid = order[1], hi = order[2];
        if (std::fabs(costs[hi] - costs[lo]) < 1e-12 * (1.0 + costs[lo])
            && std::fabs(simplex[hi][0] - simplex[lo][0]) + std::fabs(simplex[hi][1] - simplex[lo][1]) < 1e-6)
            break;
        const Point centre{(simplex[lo][0] + simplex[mid][0]) / 2, (simplex[lo][1] + simplex[mid][1]) / 2};
        auto along = [&](double k) {
            return Point{centre[0] + k * (simplex[hi][0] - centre[0]), centre[1] + k * (simplex[hi][1] - centre[1])};
        };
        const Point reflected = along(-1.0);
        const double cr = cost(reflected);
        ++evaluations;
        if (cr < costs[lo]) {
            const Point expanded = along(-2.0);
            const double ce = cost(expanded);
            ++evaluations;
            if (ce < cr) {
                simplex[hi] = expanded;
                costs[hi] = ce;
            } else {
                simplex[hi] = reflected;
                costs[hi] = cr;
            }
        } else if (cr < costs[mid]) {
            simplex[hi] = reflected;
            costs[hi] = cr;
        } else {
            const Point contracted = along(0.5);
            const double cc = cost(contracted);
            ++evaluations;
            if (cc < costs[hi]) {
                simplex[hi] = contracted;
                costs[hi] = cc;
            } else {
                for (int i : {mid, hi}) {
                    simplex[i] = Point{(simplex[i][0] + simplex[lo][0]) / 2, (simplex[i][1] + simplex[lo][1]) / 2};
                    costs[i] = cost(simplex[i]);
                    ++evaluations;
                }
            }
        }
    }
    const int lo = int(std::min_element(costs.begin(), costs.end()) - costs.begin());
    fit.model = AxisPlantModel{std::exp(simplex[lo][0]), std::exp(simplex[lo][1])};
    fit.rmsError = std::sqrt(costs[lo]) * std::fabs(step.amplitude());
    fit.ok = true;
    return fit;
}

} // namespace slew::tuning
