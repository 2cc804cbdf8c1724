// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One `slewctl --radio URI` command, from its words: `freq`, `freq 145.8M`,
// `tx 435.1M`, `split on`, `mode USB`, `txmode LSB`. Pure: no link, no I/O.

#include <QString>
#include <QStringList>

#include <optional>

namespace slew::console {

struct RadioCommand {
    enum class Kind { Read, SetReceive, SetTransmit, Split, Mode, TransmitMode };
    Kind kind = Kind::Read;
    double hz = 0;    // SetReceive, SetTransmit
    bool on = false;  // Split
    QString mode;     // Mode, TransmitMode: a Hamlib mode name, upper case
};

// The command, or nothing with a message for the operator. No words: Read.
std::optional<RadioCommand> parseRadioCommand(const QStringList &words, QString *error);

// The commands, one a line, for --help.
QString radioCommandSummary();

} // namespace slew::console
