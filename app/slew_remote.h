// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `slew --remote mqtts://USER@HOST:8883[/NAME]`: a station that lives on a
// broker, in a window (ui/stationwindow.h), or the station network
// (ui/remote/stationnetworkwindow.h). Argument parsing and wiring only.

bool wantsRemote(int argc, char **argv);

// Returns the exit code: 0 when the window closes, 2 for a bad argument.
int runRemote(int argc, char **argv);
