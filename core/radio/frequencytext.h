// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Frequencies as the Radio panel shows them: megahertz to the hertz with
// the six decimals in two groups of three (435.851 234 MHz), so the kilohertz
// an operator reads off the dial stand apart from the hertz the Doppler moves;
// and signed hertz grouped by thousands (+10 157 Hz, −3 407 Hz). Pure text.

#include <QString>

namespace slew::radio {

// "435.851 234 MHz": `hz` rounded to the hertz.
QString groupedMegahertz(double hz);

// "+1 234 Hz", "−56 Hz", "0 Hz": rounded to the hertz, the sign always
// written (a shift or an offset has a direction); "−" is the minus sign.
QString signedHertz(double hz);

// "1.2 Hz": an error figure, to a tenth.
QString tenthsOfHertz(double hz);

} // namespace slew::radio
