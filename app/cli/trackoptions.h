// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The options that say what to track, read once for the station service
// and `slew --schedule`, with the same words: --track (once, or again for
// each target of a schedule, the first the highest priority) with --tle,
// and --horizon, the station's horizon mask.

#include "sharedoptions.h"

#include "sky/horizonmask.h"
#include "tracking/tracktarget.h"

#include <QList>

#include <memory>
#include <optional>

class QCommandLineParser;

namespace slew::cli {

// Every --track in the order given: a satellite of --tle (its catalogue
// number, an AMSAT name or any part of its name; the file is read once), sun, moon,
// azel:AZ,EL or radec:RA,DEC. The same target twice is refused: a schedule
// takes each once, at one priority.
std::optional<QList<tracking::TrackTarget>> readTrackTargets(const QCommandLineParser &parser,
                                                             const OptionLabel &label, QString *error);

// --horizon FILE: the mask read from it (horizonmask.h), or null when not
// given. False with *error naming the option and the file's fault.
bool readHorizonOption(const QCommandLineParser &parser, const OptionLabel &label,
                       std::shared_ptr<const sky::HorizonMask> *mask, QString *error);

} // namespace slew::cli
