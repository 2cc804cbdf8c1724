// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The registers the wizard writes, in the operator's words: "Az I gain",
// "El park", and a value with its unit, where the wire says `CW2,14.5`.

#include <QString>

namespace slew::ui {

// "Az P gain" … "El D gain" for CW1..CW6, "Az park" and "El park" for
// CW7/CW8; "Register n" for any other.
QString registerName(int reg);
// The value as the operator reads it: a gain as it is, a park angle with
// its degree sign.
QString registerValue(int reg, const QString &value);

} // namespace slew::ui
