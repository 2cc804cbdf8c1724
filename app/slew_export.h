// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `slew --export-elements [--format FORM] [SAT…]`: the element sets Slew
// holds (--tle's file, else the window's cached sources) written in any of
// the five forms, so a program that reads only TLEs (Gpredict 2.3, say)
// can still be fed from Slew. The writing is in core/sky.

bool wantsExportElements(int argc, char **argv);

// Returns the exit code: 0 written (a set a TLE cannot carry is named on
// stderr and left out), 1 a satellite named is not there, 2 bad arguments,
// no element sets, or a file that cannot be written.
int runExportElements(int argc, char **argv);
