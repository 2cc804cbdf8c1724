// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The target a face names in words, as a command over MQTT or the face's
// track intent (face/stationface.h) names it: "az,el" or a celestial
// position (tracking/tracktarget.h), "sun", "moon", or a satellite by its
// name, part of it, or its catalogue number, looked for among the sets the
// station was given (the service's --tle) and then its element-set cache.
// One reading for every face, so a name found by one is found by all.

#include "sky/elementset.h"
#include "tracking/tracktarget.h"

#include <QList>
#include <QString>
#include <QStringList>

#include <optional>

namespace slew::station {

class Station;

// None, with *why in the operator's words, when the text names no target
// or more than one satellite.
std::optional<tracking::TrackTarget> targetByName(const Station &station, const QList<sky::ElementSet> &given,
                                                  const QString &text, QString *why);

// A schedule's targets, each found as above, in the order given; none, with
// the first one's *why, when any names no target or more than one satellite
// (the why names it).
std::optional<QList<tracking::TrackTarget>> targetsByName(const Station &station, const QList<sky::ElementSet> &given,
                                                          const QStringList &texts, QString *why);

} // namespace slew::station
