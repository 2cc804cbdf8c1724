#include "rotatorlimits.h"

#include <QObject>

#include <algorithm>
#include <cmath>

namespace slew::model {

namespace {
// Angles typed or sent by trackers carry rounding noise; a hair outside a
// limit is the limit.
constexpr double kSlack = 1e-6;
}

QString RotatorLimits::validate() const
{
    if (!std::isfinite(azMin) || !std::isfinite(azMax) || !std::isfinite(elMin) || !std::isfinite(elMax))
        return QObject::tr("limits must be numbers");
    if (azMin < -180.0 || azMin >= azMax)
        return QObject::tr("azimuth minimum %1° must be below the maximum %2°").arg(azMin).arg(azMax);
    if (azMax - azMin > 450.0 + kSlack)
        return QObject::tr("azimuth travel %1° is more than 450°").arg(azMax - azMin);
    if (elMin < -90.0 || elMin >= elMax || elMax > 180.0 + kSlack)
        return QObject::tr("elevation range %1°..%2° is not within -90°..180°").arg(elMin).arg(elMax);
    return {};
}

AzimuthChoice chooseAzimuth(const RotatorLimits &limits, double target, std::optional<double> current)
{
    if (!std::isfinite(target))
        return {std::nullopt, QObject::tr("azimuth is not a number")};
    // A bearing (0..360) may be reached at +-360 on a rotator with overlap or
    // a south stop; an angle already outside 0..360 means exactly that angle.
    const bool bearing = target >= 0.0 && target <= 360.0;
    std::optional<double> best;
    for (double candidate : {target, target + 360.0, target - 360.0}) {
        if (!bearing && candidate != target)
            continue;
        if (candidate < limits.azMin - kSlack || candidate > limits.azMax + kSlack)
            continue;
        candidate = std::clamp(candidate, limits.azMin, limits.azMax);
        if (!best) {
            best = candidate;
            continue;
        }
        if (current) {
            if (std::abs(candidate - *current) < std::abs(*best - *current))
                best = candidate;
        } else if (candidate >= 0.0 && candidate < 360.0 && !(*best >= 0.0 && *best < 360.0)) {
            best = candidate;
        }
    }
    if (!best) {
        return {std::nullopt, QObject::tr("azimuth %1° is outside the rotator's range %2°..%3°")
                                  .arg(target, 0, 'f', 1)
                                  .arg(limits.azMin, 0, 'f', 0)
                                  .arg(limits.azMax, 0, 'f', 0)};
    }
    return {best, {}};
}

QString checkElevation(const RotatorLimits &limits, double el)
{
    if (!std::isfinite(el))
        return QObject::tr("elevation is not a number");
    if (el < limits.elMin - kSlack || el > limits.elMax + kSlack) {
        return QObject::tr("elevation %1° is outside the rotator's range %2°..%3°")
            .arg(el, 0, 'f', 1)
            .arg(limits.elMin, 0, 'f', 0)
            .arg(limits.elMax, 0, 'f', 0);
    }
    return {};
}

} // namespace slew::model
