// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The command lines of slew and slew-sim, described once (programoption.h).

#include "programoption.h"

class QCommandLineParser;

namespace slew::cli {

// slew: the window, --headless, --tune, --passes, --where and
// --update-elements.
const ProgramDescription &slewProgram();
const ProgramMode &slewWindowMode();
const ProgramMode &slewHeadlessMode();
const ProgramMode &slewTuneMode();
const ProgramMode &slewPassesMode();
const ProgramMode &slewWhereMode();
const ProgramMode &slewUpdateElementsMode();
const ProgramMode &slewUpdateTranspondersMode();
const ProgramMode &slewScheduleMode();
const ProgramMode &slewPassReportMode();
const ProgramMode &slewRemoteMode();
const ProgramMode &slewExportElementsMode();

// slew-sim: the simulated rotator as a server.
const ProgramDescription &slewSimProgram();
const ProgramMode &slewSimMode();

// slewctl: one command to a rotator from a shell or a script.
const ProgramDescription &slewctlProgram();
const ProgramMode &slewctlMode();

// Gives a parser a mode's description and options, with --help and
// --version.
void describeTo(QCommandLineParser &parser, const ProgramMode &mode);

// The same, with the program's exit status (its manual's "Exit status"
// section) after the description, so --help tells a script what each code
// means.
void describeTo(QCommandLineParser &parser, const ProgramDescription &program, const ProgramMode &mode);

} // namespace slew::cli
