// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `slew --passes SAT …` and `slew --where SAT|sun|moon …`: sky questions
// answered on the terminal, with no window. The work is in core/sky.

bool wantsSky(int argc, char **argv);

// Returns the exit code: 0 answered, 1 nothing to answer with (no such
// satellite, or it cannot be propagated), 2 bad arguments.
int runSky(int argc, char **argv);

class QCommandLineParser;
class QString;
namespace slew::sky {
struct Site;
}

// The station for a sky command: --qth, else the one the window keeps
// (Sky → Station…); with `withHorizon`, its mask from --horizon, else the
// one kept with the saved station. Empty, or why not.
QString readSkyStation(const QCommandLineParser &parser, bool withHorizon, slew::sky::Site *out);
