// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Options looked for in argv itself, before any application object exists:
// main() picks the mode (the station service must not need a display) and
// the offscreen platform (for a screenshot or --help) from them. The names
// are optionnames.h's, as QCommandLineParser reads them afterwards.

#include <QString>

namespace slew::cli {

// Whether argv holds exactly --name: a switch, which takes no value.
bool argvHasSwitch(int argc, char **argv, const QString &longName);

// Whether argv holds --name VALUE or --name=VALUE.
bool argvHasOption(int argc, char **argv, const QString &longName);

} // namespace slew::cli
