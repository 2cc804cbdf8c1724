// SPDX-License-Identifier: GPL-3.0-or-later
#include "finitenumber.h"

#include "logtext.h"

#include <cmath>

namespace slew::input {
namespace {

// What a refusal quotes of the text: short, and safe for a terminal.
QString quoted(QStringView text)
{
    return QLatin1Char('\'') + loggableText(text.toString(), 40) + QLatin1Char('\'');
}

QString formatted(double x)
{
    return QString::number(x, 'g', 10);
}

} // namespace

bool NumberRange::contains(double x) const
{
    return std::isfinite(x) && x >= min && x <= max;
}

QString NumberRange::text() const
{
    return QStringLiteral("%1..%2%3").arg(formatted(min), formatted(max), QString::fromUtf8(unit));
}

std::optional<double> finiteNumber(QStringView text)
{
    bool ok = false;
    const double value = text.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(value))
        return std::nullopt;
    return value;
}

std::optional<int> wholeNumber(QStringView text)
{
    bool ok = false;
    const int value = text.trimmed().toInt(&ok);
    if (!ok)
        return std::nullopt;
    return value;
}

bool checkNumber(double value, const NumberRange &range, QString *why)
{
    if (!std::isfinite(value)) {
        if (why)
            *why = QStringLiteral("%1 is not a finite number").arg(formatted(value));
        return false;
    }
    if (!range.contains(value)) {
        if (why)
            *why = QStringLiteral("%1%2 is outside %3").arg(formatted(value), QString::fromUtf8(range.unit), range.text());
        return false;
    }
    return true;
}

std::optional<double> numberIn(QStringView text, const NumberRange &range, QString *why)
{
    bool ok = false;
    const double value = text.trimmed().toDouble(&ok);
    if (!ok) {
        if (why)
            *why = QStringLiteral("%1 is not a number").arg(quoted(text.trimmed()));
        return std::nullopt;
    }
    if (!std::isfinite(value)) {
        if (why)
            *why = QStringLiteral("%1 is not a finite number").arg(quoted(text.trimmed()));
        return std::nullopt;
    }
    if (!checkNumber(value, range, why))
        return std::nullopt;
    return value;
}

std::optional<int> wholeNumberIn(QStringView text, int min, int max, QString *why)
{
    const std::optional<int> value = wholeNumber(text);
    if (!value) {
        if (why)
            *why = QStringLiteral("%1 is not a whole number").arg(quoted(text.trimmed()));
        return std::nullopt;
    }
    if (*value < min || *value > max) {
        if (why)
            *why = QStringLiteral("%1 is outside %2..%3").arg(*value).arg(min).arg(max);
        return std::nullopt;
    }
    return value;
}

} // namespace slew::input
