// SPDX-License-Identifier: GPL-3.0-or-later
#include "tokentext.h"

#include <charconv>
#include <cmath>

namespace slew::protocol::text {

bool allDigits(QByteArrayView s)
{
    if (s.isEmpty())
        return false;
    for (char c : s) {
        if (!isDigit(c))
            return false;
    }
    return true;
}

bool startsWithMnemonic(QByteArrayView token, QByteArrayView mnemonic)
{
    if (token.size() < mnemonic.size())
        return false;
    for (qsizetype i = 0; i < mnemonic.size(); ++i) {
        if (upper(token[i]) != mnemonic[i])
            return false;
    }
    return true;
}

// A decimal number the way devices write them: optional sign, leading zeros
// (`AZ000.1`, `EL00099`), '.' or ',' as the decimal mark. Returns the count of
// decimals in *decimals. No exponent, no spaces, no trailing bytes.
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
    double value = 0.0;
    int digits = 0;
    for (; i < s.size() && isDigit(s[i]); ++i, ++digits)
        value = value * 10.0 + (s[i] - '0');
    int fraction = 0;
    if (i < s.size() && (s[i] == '.' || s[i] == ',')) {
        ++i;
        double scale = 0.1;
        for (; i < s.size() && isDigit(s[i]); ++i, ++fraction, scale /= 10.0)
            value += (s[i] - '0') * scale;
    }
    if (i != s.size() || digits + fraction == 0)
        return false;
    // Round away the binary noise of the digit-by-digit sum.
    if (fraction > 0) {
        const double p = std::pow(10.0, fraction);
        value = std::round(value * p) / p;
    }
    *out = negative ? -value : value;
    if (decimals)
        *decimals = fraction;
    return true;
}

bool parseUnsigned(QByteArrayView s, int maxDigits, double *out)
{
    if (!allDigits(s) || s.size() > maxDigits)
        return false;
    double v = 0;
    for (char c : s)
        v = v * 10.0 + (c - '0');
    *out = v;
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
bool splitIndexed(QByteArrayView rest, int *index, QByteArrayView *value)
{
    const qsizetype comma = rest.indexOf(',');
    const QByteArrayView number = comma < 0 ? rest : rest.first(comma);
    if (!allDigits(number) || number.size() > 5)
        return false;
    *index = number.toInt();
    *value = comma < 0 ? QByteArrayView() : rest.sliced(comma + 1);
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

bool isPrintable(QByteArrayView s)
{
    for (char c : s) {
        if (static_cast<unsigned char>(c) < 0x21 || static_cast<unsigned char>(c) > 0x7e)
            return false;
    }
    return true;
}

} // namespace slew::protocol::text
