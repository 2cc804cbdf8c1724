// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Small readers for the text inside a token (digits, numbers the way devices
// write them, `n,value` pairs), shared by the Easycomm and GS-232 readers.

#include <QByteArrayView>

namespace slew::protocol::text {

inline bool isDigit(char c)
{
    return c >= '0' && c <= '9';
}
inline char upper(char c)
{
    return (c >= 'a' && c <= 'z') ? char(c - 'a' + 'A') : c;
}
bool allDigits(QByteArrayView s);
// Whether token starts with mnemonic, letters compared in upper case.
bool startsWithMnemonic(QByteArrayView token, QByteArrayView mnemonic);
// A decimal number the way devices write them: optional sign, leading zeros
// (`AZ000.1`, `EL00099`), '.' or ',' as the decimal mark; *decimals gets the
// count of decimals. No exponent, no spaces, no trailing bytes.
bool parseDecimal(QByteArrayView s, double *out, int *decimals = nullptr);
bool parseUnsigned(QByteArrayView s, int maxDigits, double *out);
bool parseSigned64(QByteArrayView s, double *out);
// `n,value` as in IP0,23.5 / CR1,0.8 / AN0,65535 / SatNOGS' bare `1,0.8`.
bool splitIndexed(QByteArrayView rest, int *index, QByteArrayView *value);
// YY:MM:DD:HH:mm:SS naming a real moment: month 1..12, a day the month
// has (20YY's leap years), hour 0..23, minute and second 0..59.
bool isValidTime(QByteArrayView s);
bool isPrintable(QByteArrayView s);   // printable ASCII, no spaces

} // namespace slew::protocol::text
