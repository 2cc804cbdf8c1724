// SPDX-License-Identifier: GPL-3.0-or-later
#include "horizonmask.h"

#include "input/boundedfile.h"
#include "input/finitenumber.h"
#include "input/logtext.h"

#include <QObject>
#include <QRegularExpression>
#include <QStringConverter>

#include <algorithm>
#include <cmath>

namespace slew::sky {

namespace {

constexpr input::NumberRange kAzimuthRange{0, 360, "°"};
// Below -5° the ground is in the way anywhere a rotator stands; 90° is the zenith.
constexpr input::NumberRange kElevationRange{-5, 90, "°"};

double wrapped(double azimuthDeg)
{
    double a = std::fmod(azimuthDeg, 360.0);
    if (a < 0)
        a += 360.0;
    return a;
}

} // namespace

std::optional<HorizonMask> HorizonMask::fromPoints(const QList<HorizonPoint> &points, QString *error)
{
    auto refuse = [&](const QString &why) {
        if (error)
            *error = why;
        return std::nullopt;
    };
    if (points.isEmpty())
        return refuse(QObject::tr("no points: a mask needs at least one `azimuth elevation` line"));
    if (points.size() > kMaxHorizonPoints)
        return refuse(QObject::tr("%1 points: at most %2").arg(points.size()).arg(kMaxHorizonPoints));
    HorizonMask mask;
    for (const HorizonPoint &p : points) {
        QString why;
        if (!input::checkNumber(p.azimuthDeg, kAzimuthRange, &why))
            return refuse(QObject::tr("azimuth %1").arg(why));
        if (!input::checkNumber(p.elevationDeg, kElevationRange, &why))
            return refuse(QObject::tr("elevation %1").arg(why));
        // 360 is north again: one place for it.
        mask.m_points.append({p.azimuthDeg == 360.0 ? 0.0 : p.azimuthDeg, p.elevationDeg});
    }
    std::stable_sort(mask.m_points.begin(), mask.m_points.end(),
                     [](const HorizonPoint &a, const HorizonPoint &b) { return a.azimuthDeg < b.azimuthDeg; });
    for (qsizetype i = 2; i < mask.m_points.size(); ++i) {
        if (mask.m_points[i].azimuthDeg == mask.m_points[i - 2].azimuthDeg)
            return refuse(QObject::tr("three points at azimuth %1°: a wall is two, its foot and its top")
                              .arg(mask.m_points[i].azimuthDeg));
    }
    const auto [low, high] = std::minmax_element(
        mask.m_points.begin(), mask.m_points.end(),
        [](const HorizonPoint &a, const HorizonPoint &b) { return a.elevationDeg < b.elevationDeg; });
    mask.m_lowest = low->elevationDeg;
    mask.m_highest = high->elevationDeg;
    return mask;
}

double HorizonMask::elevationAt(double azimuthDeg) const
{
    if (m_points.isEmpty())
        return 0.0;
    if (!std::isfinite(azimuthDeg))
        return m_highest; // nowhere known: the whole mask's worst
    if (m_points.size() == 1)
        return m_points.front().elevationDeg;
    const double az = wrapped(azimuthDeg);
    // The first point at or past az; the one before it, round through north.
    const auto after = std::lower_bound(m_points.begin(), m_points.end(), az,
                                        [](const HorizonPoint &p, double a) { return p.azimuthDeg < a; });
    if (after != m_points.end() && after->azimuthDeg == az) {
        // On a point: a wall's two are both here, and the top counts.
        const auto next = std::next(after);
        return next != m_points.end() && next->azimuthDeg == az ? std::max(after->elevationDeg, next->elevationDeg)
                                                                : after->elevationDeg;
    }
    const HorizonPoint &to = after == m_points.end() ? m_points.front() : *after;
    const HorizonPoint &from = after == m_points.begin() ? m_points.back() : *std::prev(after);
    double span = to.azimuthDeg - from.azimuthDeg;
    double along = az - from.azimuthDeg;
    if (span <= 0)
        span += 360.0; // round through north
    if (along < 0)
        along += 360.0;
    return from.elevationDeg + (to.elevationDeg - from.elevationDeg) * (along / span);
}

QString HorizonMask::describe() const
{
    const auto high = std::max_element(m_points.begin(), m_points.end(), [](const HorizonPoint &a, const HorizonPoint &b) {
        return a.elevationDeg < b.elevationDeg;
    });
    const QString points = m_points.size() == 1 ? QObject::tr("1 point") : QObject::tr("%1 points").arg(m_points.size());
    return QObject::tr("%1, %2° to %3° (highest at %4°)")
        .arg(points)
        .arg(m_lowest, 0, 'f', 1)
        .arg(m_highest, 0, 'f', 1)
        .arg(high->azimuthDeg, 0, 'f', 1);
}

HorizonFile parseHorizonText(const QString &text, const QString &source)
{
    HorizonFile out;
    QList<HorizonPoint> points;
    const QStringList lines = text.split(QLatin1Char('\n'));
    for (qsizetype i = 0; i < lines.size(); ++i) {
        QString line = lines[i];
        if (const qsizetype hash = line.indexOf(QLatin1Char('#')); hash >= 0)
            line.truncate(hash);
        line = line.trimmed();
        if (line.isEmpty())
            continue;
        const QString where = QStringLiteral("%1:%2").arg(source).arg(i + 1);
        const QStringList words = line.split(QRegularExpression(QStringLiteral("[\\s,;]+")), Qt::SkipEmptyParts);
        if (words.size() != 2) {
            out.error = QObject::tr("%1: expected `azimuth elevation` (two numbers in degrees), found '%2'")
                            .arg(where, input::loggableText(line, 60));
            return out;
        }
        QString why;
        const std::optional<double> az = input::numberIn(words[0], kAzimuthRange, &why);
        if (!az) {
            out.error = QObject::tr("%1: azimuth %2").arg(where, why);
            return out;
        }
        const std::optional<double> el = input::numberIn(words[1], kElevationRange, &why);
        if (!el) {
            out.error = QObject::tr("%1: elevation %2").arg(where, why);
            return out;
        }
        if (points.size() >= kMaxHorizonPoints) {
            out.error = QObject::tr("%1: more than %2 points").arg(where).arg(kMaxHorizonPoints);
            return out;
        }
        points.append({*az, *el});
    }
    QString why;
    const std::optional<HorizonMask> mask = HorizonMask::fromPoints(points, &why);
    if (!mask) {
        out.error = QObject::tr("%1: %2").arg(source, why);
        return out;
    }
    out.mask = std::make_shared<const HorizonMask>(*mask);
    return out;
}

HorizonFile readHorizonFile(const QString &path)
{
    const input::BoundedRead read = input::readBoundedFile(path, kMaxHorizonFileBytes);
    if (!read.ok())
        return {nullptr, read.error};
    QStringDecoder utf8(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
    const QString text = utf8.decode(read.bytes);
    if (utf8.hasError())
        return {nullptr, QObject::tr("%1 is not UTF-8 text").arg(path)};
    return parseHorizonText(text, path);
}

} // namespace slew::sky
