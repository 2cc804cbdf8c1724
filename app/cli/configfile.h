// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The station service's config file (slew --headless --config FILE): one
// `name = value` a line, where name is a long option of the mode that may be
// set from a file. Blank lines and lines starting with # are ignored.
//
//     connect = serial:/dev/ttyUSB0?baud=9600
//     rotctld-listen = 127.0.0.1:4533
//
// The file stands for command-line options written before the real ones, so
// an option given on the command line wins.

#include "programoption.h"

#include <optional>

namespace slew::cli {

// The file's settings as arguments ("--connect=…"), or nothing with a
// message that names the file and line of the first problem.
std::optional<QStringList> readConfigFile(const QString &path, const ProgramMode &mode, QString *error);

// The same for text already read; `origin` names it in messages.
std::optional<QStringList> parseConfigText(const QString &text, const QString &origin, const ProgramMode &mode,
                                           QString *error);

// The command line with a config file's settings put in front of the real
// options, if the arguments name one with --config; else the arguments as
// they are. Nothing, with a message, if the file cannot be used.
std::optional<QStringList> withConfigFile(const QStringList &arguments, const ProgramMode &mode, QString *error);

} // namespace slew::cli
