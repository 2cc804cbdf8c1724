// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One slewctl command, from its words: `goto 180 30 --wait`, `config set 1
// 0.8`, `raw AZ`. Pure: no session, no I/O. The command line and the
// interactive prompt both parse through here, so they accept the same
// things and refuse them with the same words.

#include <QString>
#include <QStringList>

#include <optional>

namespace slew::console {

struct ConsoleCommand {
    enum class Kind { Get, Goto, Stop, Park, Home, Watch, Raw, ConfigGet, ConfigSet, Help, Quit };
    Kind kind = Kind::Get;
    double azimuth = 0;     // Goto
    double elevation = 0;   // Goto
    bool wait = false;      // Goto, Park, Home: return once there
    double intervalSeconds = 1; // Watch
    QString text;           // Raw: the line; ConfigSet: the value
    int reg = 0;            // ConfigGet, ConfigSet
};

// The command, or nothing with a message for the operator.
std::optional<ConsoleCommand> parseConsoleCommand(const QStringList &words, QString *error);

// Splits a prompt line into words; single or double quotes keep spaces.
QStringList splitConsoleLine(const QString &line);

// The commands, one a line, for `help` and --help.
QString consoleCommandSummary();

} // namespace slew::console
