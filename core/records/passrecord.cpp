// SPDX-License-Identifier: GPL-3.0-or-later
#include "passrecord.h"

#include "input/finitenumber.h"

namespace slew::records {

QString outcomeName(Outcome outcome)
{
    switch (outcome) {
    case Outcome::InProgress: return QStringLiteral("in progress");
    case Outcome::Tracked: return QStringLiteral("tracked");
    case Outcome::Interrupted: return QStringLiteral("interrupted");
    case Outcome::Dropped: return QStringLiteral("dropped");
    }
    return {};
}

std::optional<Outcome> outcomeFromName(const QString &name)
{
    for (Outcome o : {Outcome::InProgress, Outcome::Tracked, Outcome::Interrupted, Outcome::Dropped}) {
        if (name == outcomeName(o))
            return o;
    }
    return std::nullopt;
}

bool plausibleSample(const PassSample &s)
{
    // An azimuth of a 450° rotator or a south stop's -180..540 at most; an
    // elevation past the zenith on a flip rotator, or a little below the
    // horizon (a calibration offset, a target under -5° by refraction).
    const input::NumberRange azimuth{-360, 720, "°"}, elevation{-90, 180, "°"}, error{0, 180, "°"};
    return s.unixMs > 0 && azimuth.contains(s.antennaAzDeg) && elevation.contains(s.antennaElDeg)
           && azimuth.contains(s.targetAzDeg) && elevation.contains(s.targetElDeg) && error.contains(s.errorDeg);
}

QString boundedText(const QString &text, int chars)
{
    const QString t = text.trimmed();
    return t.size() > chars ? t.left(chars - 1) + QChar(0x2026) : t;
}

QString storedTime(const QDateTime &utc)
{
    if (!utc.isValid())
        return {};
    return utc.toUTC().toString(Qt::ISODateWithMs);
}

QDateTime timeFromStored(const QString &text)
{
    QDateTime t = QDateTime::fromString(text, Qt::ISODateWithMs);
    if (!t.isValid())
        t = QDateTime::fromString(text, Qt::ISODate);
    // Only UTC, as written: a time without its Z is not one of ours.
    if (!t.isValid() || !text.endsWith(u'Z'))
        return {};
    return t.toUTC();
}

} // namespace slew::records
