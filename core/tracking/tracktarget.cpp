// SPDX-License-Identifier: GPL-3.0-or-later
#include "tracktarget.h"

#include "input/logtext.h"

#include "skytrack.h"

#include "sky/sunmoon.h"

#include <QObject>
#include <QRegularExpression>

#include <cmath>

namespace slew::tracking {

namespace {

// The planner's sampling: a satellite moves degrees a second near the
// zenith; the sky turns a thousandth of that, and along so gentle a curve
// that a straight line between points two minutes apart is off by under a
// thousandth of a degree. The moon's theory costs 1.7 ms a position: it is
// computed every ten minutes and interpolated (sunmoon.h, geocentricPlace).
constexpr double kSatelliteStepS = 1.0;
constexpr double kSkyStepS = 120.0;
constexpr double kFixedStepS = 60.0;

// "23:23:24.5", "-5:30", "12.5": a sign, then up to three colon-separated
// parts, each after the first under 60.
std::optional<double> sexagesimal(const QString &text)
{
    static const QRegularExpression form(
        QStringLiteral("^([+-]?)(\\d+(?:\\.\\d+)?)(?::(\\d+(?:\\.\\d+)?))?(?::(\\d+(?:\\.\\d+)?))?$"));
    const QRegularExpressionMatch m = form.match(text.trimmed());
    if (!m.hasMatch())
        return std::nullopt;
    const double minutes = m.captured(3).isEmpty() ? 0.0 : m.captured(3).toDouble();
    const double seconds = m.captured(4).isEmpty() ? 0.0 : m.captured(4).toDouble();
    if (minutes >= 60.0 || seconds >= 60.0 || (!m.captured(4).isEmpty() && m.captured(3).contains(QLatin1Char('.'))))
        return std::nullopt;
    const double value = m.captured(2).toDouble() + minutes / 60.0 + seconds / 3600.0;
    if (!std::isfinite(value))
        return std::nullopt; // four hundred digits read as infinity
    return m.captured(1) == QLatin1String("-") ? -value : value;
}

sky::BodyPosition skyPosition(const TrackTarget &t, const sky::Site &station, double julian)
{
    switch (t.kind) {
    case TrackTarget::Kind::Sun: return sky::sunPosition(station, julian);
    case TrackTarget::Kind::Moon: return sky::moonPosition(station, julian);
    case TrackTarget::Kind::Celestial:
        return sky::celestialPosition(t.rightAscensionDeg, t.declinationDeg, station, julian);
    case TrackTarget::Kind::Fixed: break;
    case TrackTarget::Kind::Satellite: break;
    }
    sky::BodyPosition p;
    p.azimuthDeg = t.azimuthDeg;
    p.elevationDeg = t.elevationDeg;
    return p;
}

} // namespace

QString TrackTarget::name() const
{
    switch (kind) {
    case Kind::Sun: return QObject::tr("the sun");
    case Kind::Moon: return QObject::tr("the moon");
    case Kind::Fixed:
        return QObject::tr("azimuth %1°, elevation %2°").arg(azimuthDeg, 0, 'f', 2).arg(elevationDeg, 0, 'f', 2);
    case Kind::Celestial:
        return QObject::tr("RA %1h, Dec %2° (J2000)").arg(rightAscensionDeg / 15.0, 0, 'f', 4).arg(declinationDeg, 0, 'f', 3);
    case Kind::Satellite: break;
    }
    return elements.name.isEmpty() ? QString::number(elements.catalogueNumber) : elements.name;
}

std::optional<TrackTarget> TrackTarget::parseFixedOrCelestial(const QString &spec, QString *error)
{
    const QString text = spec.trimmed();
    const bool azel = text.startsWith(QLatin1String("azel:"), Qt::CaseInsensitive);
    const bool radec = text.startsWith(QLatin1String("radec:"), Qt::CaseInsensitive);
    if (!azel && !radec)
        return std::nullopt;
    const QStringList parts = text.mid(text.indexOf(QLatin1Char(':')) + 1).split(QLatin1Char(','));
    auto fail = [&](const QString &why) {
        if (error)
            *error = why;
        return std::nullopt;
    };
    if (parts.size() != 2)
        return fail(azel ? QObject::tr("'%1': write azel:AZ,EL").arg(input::loggableText(text, 80))
                         : QObject::tr("'%1': write radec:RA,DEC").arg(input::loggableText(text, 80)));
    TrackTarget t;
    if (azel) {
        const auto az = sexagesimal(parts[0]), el = sexagesimal(parts[1]);
        if (!az || !el || *az < 0 || *az >= 360 || *el < -5 || *el > 90)
            return fail(QObject::tr("'%1': azimuth 0..360 and elevation -5..90 degrees").arg(input::loggableText(text, 80)));
        t.kind = Kind::Fixed;
        t.azimuthDeg = *az;
        t.elevationDeg = *el;
        return t;
    }
    QString ra = parts[0].trimmed();
    const bool inDegrees = ra.endsWith(QLatin1Char('d'), Qt::CaseInsensitive);
    if (inDegrees || ra.endsWith(QLatin1Char('h'), Qt::CaseInsensitive))
        ra.chop(1);
    const auto raValue = sexagesimal(ra), dec = sexagesimal(parts[1]);
    if (!raValue || *raValue < 0 || *raValue >= (inDegrees ? 360.0 : 24.0))
        return fail(QObject::tr("'%1': right ascension is in hours, 0..24 (or degrees with a d: 350.85d)").arg(input::loggableText(parts[0], 40)));
    if (!dec || *dec < -90 || *dec > 90)
        return fail(QObject::tr("'%1': declination is -90..90 degrees").arg(input::loggableText(parts[1], 40)));
    t.kind = Kind::Celestial;
    t.rightAscensionDeg = inDegrees ? *raValue : *raValue * 15.0;
    t.declinationDeg = *dec;
    return t;
}

TargetSky::TargetSky(const TrackTarget &target) : m_target(target)
{
    if (target.kind == TrackTarget::Kind::Satellite) {
        m_satellite = std::make_shared<const sky::Sgp4>(target.elements);
        m_ticking.emplace(*m_satellite);
    }
}

QList<sky::Pass> TargetSky::passes(const sky::Site &station, const sky::PassWindow &window) const
{
    switch (m_target.kind) {
    case TrackTarget::Kind::Satellite: return sky::predictPasses(*m_satellite, station, window);
    case TrackTarget::Kind::Sun: return sky::predictBodyPasses(sky::SkyBody::Sun, station, window);
    case TrackTarget::Kind::Moon: return sky::predictBodyPasses(sky::SkyBody::Moon, station, window);
    case TrackTarget::Kind::Celestial:
        return sky::predictCelestialPasses(m_target.rightAscensionDeg, m_target.declinationDeg, station, window);
    case TrackTarget::Kind::Fixed: break;
    }
    if (m_target.elevationDeg < window.minElevationDeg || m_target.elevationDeg < window.leastHighestDeg
        || (station.horizon && m_target.elevationDeg < station.horizon->elevationAt(m_target.azimuthDeg)))
        return {}; // below the minimum, or behind what hides the sky there
    sky::Pass held;
    held.name = m_target.name();
    const sky::PassPoint point{0, m_target.azimuthDeg, m_target.elevationDeg};
    held.aos = held.tca = held.los = point;
    held.aos.julian = held.tca.julian = window.startJulian;
    held.los.julian = window.endJulian;
    held.losClipped = true;
    return {held};
}

QList<SkyPoint> TargetSky::sample(const sky::Site &station, const sky::Pass &pass, double fromJulian) const
{
    if (m_satellite) {
        sky::Pass rest = pass;
        rest.aos.julian = fromJulian;
        return sampleSatellitePass(*m_satellite, station, rest, kSatelliteStepS);
    }
    if (m_target.kind == TrackTarget::Kind::Sun || m_target.kind == TrackTarget::Kind::Moon) {
        // The theory every ten minutes, a straight line between (sunmoon.h).
        const sky::SkyBody body = m_target.kind == TrackTarget::Kind::Sun ? sky::SkyBody::Sun : sky::SkyBody::Moon;
        constexpr double kNodeDays = 600.0 / sky::kSecondsPerDay;
        double nodeAt = fromJulian;
        sky::GeocentricPlace node = sky::geocentricPlace(body, nodeAt);
        sky::GeocentricPlace nextNode = sky::geocentricPlace(body, nodeAt + kNodeDays);
        return sampleSkyPass(
            [&](double julian) {
                while (julian > nodeAt + kNodeDays) {
                    nodeAt += kNodeDays;
                    node = nextNode;
                    nextNode = sky::geocentricPlace(body, nodeAt + kNodeDays);
                }
                const double f = (julian - nodeAt) / kNodeDays;
                const double turn = std::remainder(nextNode.rightAscensionDeg - node.rightAscensionDeg, 360.0);
                const sky::GeocentricPlace between{node.rightAscensionDeg + f * turn,
                                                   node.declinationDeg + f * (nextNode.declinationDeg - node.declinationDeg),
                                                   node.distanceKm + f * (nextNode.distanceKm - node.distanceKm)};
                return sky::bodyPositionFrom(between, station, julian);
            },
            fromJulian, pass.los.julian, kSkyStepS);
    }
    return sampleSkyPass([&](double julian) { return skyPosition(m_target, station, julian); }, fromJulian,
                         pass.los.julian, m_target.isFixed() ? kFixedStepS : kSkyStepS);
}

std::optional<sky::LookAngles> TargetSky::lookAt(const sky::Site &station, double julian)
{
    sky::LookAngles look;
    if (m_ticking) {
        if (!sky::observeSatellite(*m_ticking, station, julian, &look))
            return std::nullopt;
        return look;
    }
    const sky::BodyPosition p = skyPosition(m_target, station, julian);
    look.azimuthDeg = p.azimuthDeg;
    look.elevationDeg = p.elevationDeg;
    look.rangeKm = p.distanceKm;
    return look;
}

} // namespace slew::tracking
