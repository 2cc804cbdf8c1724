#pragma once
// `slew --headless`: Slew as a station service with no window and no display.

// Returns the process exit code. Called from main() before any GUI object
// exists, so no display is needed.
int runHeadless(int argc, char *argv[]);

// Whether the command line asks for headless mode.
bool wantsHeadless(int argc, char *argv[]);
