#pragma once
// `slew --tune URI --axis az|el|both [--apply]`: the tuning engine with no
// window; prints a before/after table.

// Whether the command line asks for a tuning run.
bool wantsTune(int argc, char **argv);

// Returns the process exit code: 0 tuned, 1 the tuning failed or was
// cancelled, 2 bad arguments. Called from main() before any GUI object exists.
int runTune(int argc, char **argv);
