// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `slew --pass-report ID --out FILE.png [--pass-db FILE]`: the picture of a
// recorded pass, written with no display. The drawing is in slewui
// (passreportpicture.h), the records in core/records.

bool wantsPassReport(int argc, char **argv);

// Returns the exit code: 0 written; 1 no such pass, no samples of it, or
// no records at all (nothing written); 2 bad arguments or records that
// cannot be read.
int runPassReport(int argc, char **argv);
