// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where slew-sim keeps a Micro-2g controller's calibration, presets and
// tolerances between runs (`--state-file PATH`): the real program loses them
// at power-off, so without the option the simulator does too.
//
// A JSON file, written whole through QSaveFile so that a crash mid-write
// leaves the previous state, not half of one.

#include <QString>

namespace slew::sim {

class Micro2gController;

// Restores what the file holds. A missing file is a first run: nothing to
// restore, no error. Returns what is wrong otherwise, and changes nothing.
QString loadMicro2gState(const QString &path, Micro2gController &controller);
// Writes the controller's settings; returns what went wrong, if anything.
QString saveMicro2gState(const QString &path, const Micro2gController &controller);

} // namespace slew::sim
