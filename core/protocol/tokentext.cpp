// SPDX-License-Identifier: GPL-3.0-or-later
#include "tokentext.h"

#include <charconv>
#include <cstdint>
#include <iterator>
#include <system_error>

namespace slew::protocol::text {

bool parseDecimal(QByteArrayView s, double *out, int *decimals)
{
    if (s.isEmpty() || s.size() > 24)
        return false;
    qsizetype i = 0;
    bool negative = false;
    if (s[0] == '+' || s[0] == '-') {
        negative = s[0] == '-';
        ++i;
    }
    // The digits as one whole number and a power of ten to divide it by: one
    // correctly rounded division, the nearest double to what was written for
    // the up to 15 digits a device sends, and no pow() per reply.
    std::uint64_t mantissa = 0;
    int digits = 0;
    for (; i < s.size() && isDigit(s[i]); ++i, ++digits)
        mantissa = mantissa * 10 + std::uint64_t(s[i] - '0');
    int fraction = 0;
    if (i < s.size() && (s[i] == '.' || s[i] == ',')) {
        ++i;
        for (; i < s.size() && isDigit(s[i]); ++i, ++fraction)
            mantissa = mantissa * 10 + std::uint64_t(s[i] - '0');
    }
    if (i != s.size() || digits + fraction == 0)
        return false;
    static constexpr double kPowersOfTen[] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                              1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
    constexpr int kExactDigits = 15; // any whole number of 15 digits is exact in a double
    double value = 0.0;
    if (digits + fraction <= kExactDigits) {
        // Both exact in a double, so the quotient is correctly rounded.
        value = double(mantissa) / kPowersOfTen[fraction];
    } else {
        // More digits than are sure to be exact (the whole number may have
        // wrapped too): from_chars reads it correctly rounded, whatever the
        // locale. Leading zeros count here, to keep the digit loops bare.
        char copy[32];
        const QByteArrayView digitsOnly = s.sliced(s[0] == '+' || s[0] == '-' ? 1 : 0);
        for (qsizetype k = 0; k < digitsOnly.size(); ++k)
            copy[k] = digitsOnly[k] == ',' ? '.' : digitsOnly[k];
        if (std::from_chars(copy, copy + digitsOnly.size(), value).ec != std::errc())
            return false;
    }
    *out = negative ? -value : value;
    if (decimals)
        *decimals = fraction;
    return true;
}

bool parseSigned64(QByteArrayView s, double *out)
{
    long long v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size() || s.isEmpty())
        return false;
    *out = double(v);
    return true;
}

// `n,value` as in IP0,23.5 / CR1,0.8 / AN0,65535 / SatNOGS' bare `1,0.8`.
bool splitIndexed(QByteArrayView rest, int *index, std::optional<QByteArrayView> *value)
{
    const qsizetype comma = rest.indexOf(',');
    const QByteArrayView number = comma < 0 ? rest : rest.first(comma);
    if (!allDigits(number) || number.size() > 5)
        return false;
    *index = digitsValue(number);
    *value = comma < 0 ? std::nullopt : std::optional<QByteArrayView>(rest.sliced(comma + 1));
    return true;
}

bool isValidTime(QByteArrayView s)
{
    // YY:MM:DD:HH:mm:SS
    if (s.size() != 17)
        return false;
    int field[6] = {};
    for (qsizetype i = 0; i < s.size(); ++i) {
        const bool colon = (i % 3) == 2;
        if (colon ? s[i] != ':' : !isDigit(s[i]))
            return false;
        if (!colon)
            field[i / 3] = field[i / 3] * 10 + (s[i] - '0');
    }
    const int year = 2000 + field[0], month = field[1], day = field[2];
    if (month < 1 || month > 12 || day < 1)
        return false;
    static constexpr int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
    const int days = kDays[month - 1] + (month == 2 && leap ? 1 : 0);
    return day <= days && field[3] <= 23 && field[4] <= 59 && field[5] <= 59;
}

} // namespace slew::protocol::text
