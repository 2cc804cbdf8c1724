// SPDX-License-Identifier: GPL-3.0-or-later
#include "movegate.h"

#include <QObject>

#include <algorithm>
#include <cmath>

namespace slew::model {

namespace {

// A hair outside a limit (rounding in a tracker's numbers) is the limit.
constexpr double kSlack = 1e-6;

QString byTheLink(const QString &refusal)
{
    return QObject::tr("%1 (the limits the link reports)").arg(refusal);
}

QString outsideAzimuth(double azimuth, const RotatorLimits &limits)
{
    return QObject::tr("azimuth %1° is outside the rotator's range %2°..%3°")
        .arg(azimuth, 0, 'f', 1)
        .arg(limits.azMin, 0, 'f', 0)
        .arg(limits.azMax, 0, 'f', 0);
}

// Asked of the profile's limits first, so that a refusal names the limits
// that refused: the profile's, or the narrower ones the link reports.
template <typename Check>
QString refusalOf(const RotatorLimits &profile, const RotatorLimits &inForce, bool narrowed, Check check)
{
    if (QString e = check(profile); !e.isEmpty())
        return e;
    if (!narrowed)
        return {};
    if (QString e = check(inForce); !e.isEmpty())
        return byTheLink(e);
    return {};
}

} // namespace

MoveGate::MoveGate(const RotatorLimits &profile, std::optional<RotatorLimits> reported)
    : m_profile(profile), m_reported(reported)
{
}

RotatorLimits MoveGate::limits() const
{
    if (!m_reported)
        return m_profile;
    return RotatorLimits{std::max(m_profile.azMin, m_reported->azMin), std::min(m_profile.azMax, m_reported->azMax),
                         std::max(m_profile.elMin, m_reported->elMin), std::min(m_profile.elMax, m_reported->elMax)};
}

MoveCheck MoveGate::azimuthBearing(double azimuth, std::optional<double> currentAzimuth) const
{
    const RotatorLimits inForce = limits();
    MoveCheck c;
    c.refusal = refusalOf(m_profile, inForce, m_reported.has_value(), [&](const RotatorLimits &l) {
        return chooseAzimuth(l, azimuth, currentAzimuth).error;
    });
    if (c.allowed())
        c.azimuth = *chooseAzimuth(inForce, azimuth, currentAzimuth).azimuth;
    return c;
}

MoveCheck MoveGate::azimuthPosition(double azimuth) const
{
    MoveCheck c;
    c.refusal = refusalOf(m_profile, limits(), m_reported.has_value(), [&](const RotatorLimits &l) {
        if (!std::isfinite(azimuth))
            return QObject::tr("azimuth is not a number");
        if (azimuth < l.azMin - kSlack || azimuth > l.azMax + kSlack)
            return outsideAzimuth(azimuth, l);
        return QString();
    });
    if (c.allowed())
        c.azimuth = std::clamp(azimuth, limits().azMin, limits().azMax);
    return c;
}

MoveCheck MoveGate::elevation(double elevation) const
{
    MoveCheck c;
    c.refusal = refusalOf(m_profile, limits(), m_reported.has_value(),
                          [&](const RotatorLimits &l) { return checkElevation(l, elevation); });
    if (c.allowed())
        c.elevation = std::clamp(elevation, limits().elMin, limits().elMax);
    return c;
}

MoveCheck MoveGate::pointing(double azimuth, double elevation, std::optional<double> currentAzimuth) const
{
    // Elevation first: it has one answer, and says the plainer thing.
    MoveCheck el = this->elevation(elevation);
    if (!el.allowed())
        return el;
    MoveCheck c = azimuthBearing(azimuth, currentAzimuth);
    c.elevation = el.elevation;
    return c;
}

MoveCheck MoveGate::mechanical(double azimuth, double elevation) const
{
    MoveCheck el = this->elevation(elevation);
    if (!el.allowed())
        return el;
    MoveCheck c = azimuthPosition(azimuth);
    c.elevation = el.elevation;
    return c;
}

MoveCheck MoveGate::drive(bool azimuthAxis, bool positive, std::optional<double> at) const
{
    MoveCheck c;
    if (!at)
        return c; // nothing known to refuse on; the controller's own limits hold
    const RotatorLimits l = limits();
    const double limit = positive ? (azimuthAxis ? l.azMax : l.elMax) : (azimuthAxis ? l.azMin : l.elMin);
    if (positive ? *at >= limit - kSlack : *at <= limit + kSlack) {
        c.refusal = QObject::tr("%1 is already at its %2 limit (%3°)")
                        .arg(azimuthAxis ? QObject::tr("azimuth") : QObject::tr("elevation"),
                             positive ? QObject::tr("upper") : QObject::tr("lower"))
                        .arg(limit, 0, 'f', 1);
    }
    return c;
}

} // namespace slew::model
