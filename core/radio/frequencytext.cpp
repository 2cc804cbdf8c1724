// SPDX-License-Identifier: GPL-3.0-or-later
#include "frequencytext.h"

#include <cmath>

namespace slew::radio {

namespace {

// "1234567" as "1 234 567".
QString thousands(qint64 whole)
{
    QString digits = QString::number(whole);
    for (qsizetype at = digits.size() - 3; at > 0; at -= 3)
        digits.insert(at, QLatin1Char(' '));
    return digits;
}

} // namespace

QString groupedMegahertz(double hz)
{
    if (!std::isfinite(hz))
        return QStringLiteral("—");
    const qint64 whole = qint64(std::llround(std::abs(hz)));
    const QString fraction = QStringLiteral("%1").arg(whole % 1000000, 6, 10, QLatin1Char('0'));
    return QStringLiteral("%1%2.%3 %4 MHz")
        .arg(hz < 0 ? QStringLiteral("−") : QString())
        .arg(whole / 1000000)
        .arg(fraction.left(3), fraction.mid(3));
}

QString signedHertz(double hz)
{
    if (!std::isfinite(hz))
        return QStringLiteral("—");
    const qint64 whole = qint64(std::llround(hz));
    const QString sign = whole > 0 ? QStringLiteral("+") : whole < 0 ? QStringLiteral("−") : QString();
    return QStringLiteral("%1%2 Hz").arg(sign, thousands(whole < 0 ? -whole : whole));
}

QString tenthsOfHertz(double hz)
{
    return std::isfinite(hz) ? QStringLiteral("%1 Hz").arg(hz, 0, 'f', 1) : QStringLiteral("—");
}

} // namespace slew::radio
