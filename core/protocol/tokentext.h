// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Small readers for the text inside a token (digits, numbers the way devices
// write them, `n,value` pairs), shared by the Easycomm and GS-232 readers.
// Those every token passes through are defined here, inline: called across
// translation units they cost a call per byte, which halved the parser's
// throughput when they moved out of the reader.

#include <QByteArrayView>

#include <optional>

namespace slew::protocol::text {

inline bool isDigit(char c)
{
    return c >= '0' && c <= '9';
}
inline char upper(char c)
{
    return (c >= 'a' && c <= 'z') ? char(c - 'a' + 'A') : c;
}
inline bool allDigits(QByteArrayView s)
{
    if (s.isEmpty())
        return false;
    for (char c : s) {
        if (!isDigit(c))
            return false;
    }
    return true;
}
// The value of digits allDigits() accepted, at most 9 of them so that it fits
// an int. Not QByteArrayView::toInt(): it goes through QLocaleData, a chain
// of calls per indexed reply for a few digits.
inline int digitsValue(QByteArrayView digits)
{
    int v = 0;
    for (char c : digits)
        v = v * 10 + (c - '0');
    return v;
}
// Whether token starts with mnemonic (given in capitals), letters compared
// in upper case. Pass literals or QByteArrayView constants: their length is
// known without measuring.
inline bool startsWithMnemonic(QByteArrayView token, QByteArrayView mnemonic)
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
// (`AZ000.1`, `EL00099`), '.' or ',' as the decimal mark; *decimals gets the
// count of decimals. No exponent, no spaces, no trailing bytes.
bool parseDecimal(QByteArrayView s, double *out, int *decimals = nullptr);
inline bool parseUnsigned(QByteArrayView s, int maxDigits, double *out)
{
    if (!allDigits(s) || s.size() > maxDigits)
        return false;
    double v = 0;
    for (char c : s)
        v = v * 10.0 + (c - '0');
    *out = v;
    return true;
}
bool parseSigned64(QByteArrayView s, double *out);
// `n,value` as in IP0,23.5 / CR1,0.8 / AN0,65535 / SatNOGS' bare `1,0.8`;
// *value is what follows the comma, none when there is no comma.
bool splitIndexed(QByteArrayView rest, int *index, std::optional<QByteArrayView> *value);
// YY:MM:DD:HH:mm:SS naming a real moment: month 1..12, a day the month
// has (20YY's leap years), hour 0..23, minute and second 0..59.
bool isValidTime(QByteArrayView s);
inline bool isPrintable(QByteArrayView s) // printable ASCII, no spaces
{
    for (char c : s) {
        if (static_cast<unsigned char>(c) < 0x21 || static_cast<unsigned char>(c) > 0x7e)
            return false;
    }
    return true;
}

} // namespace slew::protocol::text
