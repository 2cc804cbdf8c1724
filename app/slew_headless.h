// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `slew --headless`: Slew as a station service with no window and no display.

#include <QString>

#include <optional>

// Returns the process exit code. Called from main() before any GUI object
// exists, so no display is needed.
int runHeadless(int argc, char *argv[]);

// Whether the command line asks for headless mode.
bool wantsHeadless(int argc, char *argv[]);

// `--rotctld-max-clients N` (both modes): 1..100000, or nothing if not that.
std::optional<int> parseMaxClients(const QString &text);
