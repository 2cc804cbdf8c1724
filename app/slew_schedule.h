// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `slew --schedule --track A --track B … --qth …`: the plan the station
// service would follow for these targets, printed. The work is in
// core/schedule.

bool wantsSchedule(int argc, char **argv);

// Returns the exit code: 0 planned (whatever it took), 2 bad arguments.
int runSchedule(int argc, char **argv);
