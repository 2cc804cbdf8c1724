// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one rule for numbers that come from outside Slew: a file, an option,
// a setting, a network answer, a device. Qt's QString::toDouble() and
// strtod() take "nan", "inf" and "1e999" (which overflows to infinity), and
// a NaN passes every range check written as `x < min || x > max`, so every
// reader here refuses anything that is not a finite number, and a range is
// checked in the way NaN cannot slip through. Pure code.
//
// A refusal says what was wrong with the text; the caller puts in front of
// it where the text came from ("--min-el", "station.conf:4", a URL), so the
// user is told both.

#include <QString>
#include <QStringView>

#include <cmath>
#include <optional>

namespace slew::input {

// A closed interval [min, max]; `unit` is printed after the numbers in a
// refusal ("°", " m", " hours"), and may be empty.
struct NumberRange {
    double min = 0;
    double max = 0;
    const char *unit = "";

    // True only for a finite x with min <= x <= max; false for NaN.
    bool contains(double x) const;
    // "-5..90°"
    QString text() const;
};

// The value of `text` (spaces around it allowed) when it is a finite
// decimal number; nothing for "nan", "inf", "1e999", "", "12abc".
std::optional<double> finiteNumber(QStringView text);

// A whole number in int's range; nothing otherwise.
std::optional<int> wholeNumber(QStringView text);

// A finite number of `text` inside `range`; otherwise nothing, and *why
// (when given) says, e.g., "'nan' is not a finite number" or
// "100 is outside -5..90°".
std::optional<double> numberIn(QStringView text, const NumberRange &range, QString *why = nullptr);

// The same for a number already read (JSON, a computation, a device).
bool checkNumber(double value, const NumberRange &range, QString *why = nullptr);

// A whole number inside [min, max]; *why as above.
std::optional<int> wholeNumberIn(QStringView text, int min, int max, QString *why = nullptr);

// True when every one of the values is finite.
template <typename... T>
bool allFinite(T... values)
{
    return (std::isfinite(double(values)) && ...);
}

} // namespace slew::input
