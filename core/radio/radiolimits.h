// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The limits radio links keep, whatever carries their commands (rigctld
// over TCP, libhamlib in process, the rotator controller's UP/DN): what
// goes to a radio, what is taken from one, and how long an answer is
// waited for. One place, so the backends cannot drift apart; the exchange
// script (scriptedradiolink.h), its backends (rigctldperformer.h,
// hamlibperformer.h) and the controller's link (controllerradio.h) read
// them here. What goes to a radio is refused by every link in the same
// words (frequencyRefusal(), modeRefusal()).

#include "input/finitenumber.h"

#include <QString>
#include <QtGlobal>

namespace slew::radio::limits {

// What Slew tunes: from 1 Hz to 1 THz (a 10 GHz transverter's IF and its
// LO included). rigctld 4.5.4 with its dummy rig answers `F nan` with
// RPRT 0 and then reads -9223372036854775808, so nothing outside this goes
// to a radio, and a reading outside it is not believed.
inline constexpr input::NumberRange kFrequencyRange{1, 1e12, " Hz"};

// A tuning step read from a radio: 0 (the radio has none set, as rigctld's
// dummy rig says) to 1 MHz, the coarsest step a radio lists. 0, a refused
// get_ts (a backend without it answers RPRT -11), or a reading outside the
// range leave the step at kUnknownStepHz: quantising to 1 Hz changes nothing.
inline constexpr input::NumberRange kStepRange{0, 1e6, " Hz"};
inline constexpr double kUnknownStepHz = 1.0;

// Hamlib's passband: -1 keeps the radio's, 0 asks for the mode's default;
// 1 MHz is wider than any mode's filter.
inline constexpr int kMinPassbandHz = -1;
inline constexpr int kMaxPassbandHz = 1000000;

// A mode name as Hamlib writes them (USB, PKTUSB, FMN): letters and digits,
// at most this long. One token: no space or line end can add an argument
// or a command of its own on rigctld's line, and no NUL can end Hamlib's C
// string early ("USB\0x" would read as USB).
inline constexpr qsizetype kMaxModeChars = 16;

// How long a command may go unanswered before the link closes. Above
// Hamlib's own give-up time for a silent radio (its timeout times its
// retries, a few seconds), so Hamlib's timeout answer (RPRT -5, or
// -RIG_ETIMEOUT in process) comes first; this catches a peer that never
// answers at all (a program that speaks rigctld's protocol and ignores a
// command it does not know).
inline constexpr int kReplyTimeoutMs = 10000;

// Timeouts in a row, each after Hamlib's own retries, that close the link:
// one is a busy radio, two a radio that is gone (switched off, its cable
// pulled). An I/O or protocol error closes it at once.
inline constexpr int kTimeoutsBeforeClosing = 2;

// How long reaching rigctld's port may take: a local network answers in
// milliseconds, a host that is down never does.
inline constexpr int kConnectTimeoutMs = 5000;

// The latency a link reports is the round trip of the opening's set of the
// frequency it has just read (a change of nothing on the radio): a set
// always reaches the radio, where Hamlib answers a get from its cache, and
// above 100 MHz Hamlib reads the frequency back before it answers, so a
// set's round trip is the command-to-read-back the Doppler steering lives
// with. Timed from the moment the command leaves the link to its answer.

// Why no radio is given this frequency, as every link says it when it
// refuses one ("not sent: 0.4 Hz is outside 1..1e+12 Hz"); empty when it
// is inside kFrequencyRange.
QString frequencyRefusal(double hz);
// The same for a mode name and its passband (kMaxModeChars,
// kMinPassbandHz..kMaxPassbandHz).
QString modeRefusal(const QString &mode, int passbandHz);

} // namespace slew::radio::limits
