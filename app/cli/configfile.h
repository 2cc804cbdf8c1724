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
// an option given on the command line wins. Every refusal names the file and
// the line, whether the fault is in the file's form (an unknown name, a name
// given twice) or in a value found later (a port out of range): the
// arguments carry where each setting came from.

#include "programoption.h"

#include <QHash>

#include <optional>

namespace slew::cli {

// The command line with a config file's settings in front, and where each
// setting that the file gave (and the command line did not override) came
// from.
struct ConfiguredArguments {
    QStringList arguments;
    QHash<QString, QString> origins; // long name -> "FILE:LINE"

    // How a message names the option `longName`: "station.conf:4:
    // rotctld-listen" when the file gave it, else "--rotctld-listen".
    QString label(const QString &longName) const;
};

// A config file is a few lines; a file over this is not one.
inline constexpr qint64 kLargestConfigFile = 64 * 1024;

// The file's settings, or nothing with a message that names the file and
// line of the first problem. The file must be a regular file (not a device
// or a FIFO) of at most kLargestConfigFile.
std::optional<ConfiguredArguments> readConfigFile(const QString &path, const ProgramMode &mode, QString *error);

// The same for text already read; `origin` names it in messages.
std::optional<ConfiguredArguments> parseConfigText(const QString &text, const QString &origin,
                                                   const ProgramMode &mode, QString *error);

// The command line with a config file's settings put in front of the real
// options, if the arguments name one with --config; else the arguments as
// they are. Nothing, with a message, if the file cannot be used.
std::optional<ConfiguredArguments> withConfigFile(const QStringList &arguments, const ProgramMode &mode,
                                                  QString *error);

} // namespace slew::cli
