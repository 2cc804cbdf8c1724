// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The broker password, never from the command line (it would show in `ps`
// and the shell's history): the first line of a file the operator names
// (--mqtt-password-file, `mqtt-password-file =` in the service's config
// file), or the environment variable SLEW_MQTT_PASSWORD.

#include <QString>

#include <optional>

namespace slew::remote {

inline constexpr char kPasswordVariable[] = "SLEW_MQTT_PASSWORD";
// A password file holds one line; anything larger is not one.
inline constexpr qint64 kLargestPasswordFile = 4096;

// The first line of `path` (a regular file of at most kLargestPasswordFile
// that other users cannot read), without its line end. Nothing, with
// *error naming the file and the fault, otherwise.
std::optional<QString> readPasswordFile(const QString &path, QString *error);

// The password from `file` when one is named, else from SLEW_MQTT_PASSWORD,
// else none (an empty string: a broker that asks for none).
std::optional<QString> brokerPassword(const QString &file, QString *error);

} // namespace slew::remote
