// SPDX-License-Identifier: GPL-3.0-or-later
#include "finitenumber.h"

#include "logtext.h"

#include <charconv>
#include <cmath>
#include <cstdint>

namespace slew::input {
namespace {

enum class Parsed { Number, NotANumber, NotFinite };

// Plain decimals ("-0.0001234", "15.72125391") of at most 15 digits, the
// common case in element sets: the digits as one whole number divided by a
// power of ten. Both are exact in a double, so the one division is correctly
// rounded, the same double std::from_chars gives, at a fraction of its cost
// (libstdc++ 12's from_chars for double goes through strtod). Anything else
// (an exponent, more digits) returns false and takes the general path.
bool readPlainDecimal(const char *s, qsizetype size, double *out)
{
    qsizetype i = 0;
    const bool negative = size > 0 && s[0] == '-';
    if (negative)
        ++i;
    std::uint64_t mantissa = 0;
    int digits = 0;
    int fraction = 0;
    for (; i < size && s[i] >= '0' && s[i] <= '9'; ++i, ++digits)
        mantissa = mantissa * 10 + std::uint64_t(s[i] - '0');
    if (i < size && s[i] == '.') {
        for (++i; i < size && s[i] >= '0' && s[i] <= '9'; ++i, ++fraction)
            mantissa = mantissa * 10 + std::uint64_t(s[i] - '0');
    }
    constexpr int kExactDigits = 15; // any whole number of 15 digits is exact in a double
    if (i != size || digits + fraction == 0 || digits + fraction > kExactDigits)
        return false;
    static constexpr double kPowersOfTen[] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                              1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
    const double value = double(mantissa) / kPowersOfTen[fraction];
    *out = negative ? -value : value;
    return true;
}

// A decimal number, as QString::toDouble() reads it in the C locale, but
// without its conversion to a temporary byte string: element-set files
// hold a couple of hundred thousand numbers, and that allocation was most
// of their reading time. std::from_chars is exact (the nearest double), as
// Qt's reader is. Text it cannot take whole (too long, or out of range)
// goes to Qt's reader, so the two never disagree.
Parsed parseDecimal(QStringView text, double *out)
{
    QStringView t = text.trimmed();
    if (t.startsWith(u'+') && !t.startsWith(QLatin1StringView("+-")) && !t.startsWith(QLatin1StringView("++")))
        t = t.mid(1);
    char buffer[64];
    const qsizetype size = t.size();
    bool ascii = size > 0 && size < qsizetype(sizeof buffer);
    for (qsizetype i = 0; ascii && i < size; ++i) {
        const char16_t c = t[i].unicode();
        ascii = c > 0x20 && c < 0x7f;
        buffer[i] = char(c);
    }
    if (ascii) {
        double value = 0;
        if (readPlainDecimal(buffer, size, &value)) {
            *out = value;
            return Parsed::Number;
        }
        const auto [end, error] = std::from_chars(buffer, buffer + size, value);
        if (error == std::errc() && end == buffer + size) {
            *out = value;
            return std::isfinite(value) ? Parsed::Number : Parsed::NotFinite;
        }
        if (error != std::errc::result_out_of_range)
            return Parsed::NotANumber;
    }
    bool ok = false;
    const double value = text.trimmed().toDouble(&ok);
    *out = value;
    if (!ok)
        return std::isinf(value) ? Parsed::NotFinite : Parsed::NotANumber;
    return std::isfinite(value) ? Parsed::Number : Parsed::NotFinite;
}

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
    double value = 0;
    if (parseDecimal(text, &value) != Parsed::Number)
        return std::nullopt;
    return value;
}

std::optional<int> wholeNumber(QStringView text)
{
    // Digits with an optional sign, as QString::toInt() takes them, read
    // without a temporary string.
    QStringView t = text.trimmed();
    if (t.startsWith(u'+'))
        t = t.mid(1);
    char buffer[16];
    if (t.isEmpty() || t.size() >= qsizetype(sizeof buffer))
        return std::nullopt;
    for (qsizetype i = 0; i < t.size(); ++i) {
        const char16_t c = t[i].unicode();
        if (!((c >= u'0' && c <= u'9') || (i == 0 && c == u'-')))
            return std::nullopt;
        buffer[i] = char(c);
    }
    int value = 0;
    const auto [end, error] = std::from_chars(buffer, buffer + t.size(), value);
    if (error != std::errc() || end != buffer + t.size())
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
    double value = 0;
    const Parsed parsed = parseDecimal(text, &value);
    if (parsed == Parsed::NotANumber) {
        if (why)
            *why = QStringLiteral("%1 is not a number").arg(quoted(text.trimmed()));
        return std::nullopt;
    }
    if (parsed == Parsed::NotFinite) {
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
