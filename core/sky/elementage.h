// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How far from its epoch an element set is trusted: one rule, applied by
// everything that predicts for the rotator (the schedule, one target's
// passes, the Tracking tab's age line, the Element sets dialog).
//
// SGP4's error grows with the distance from the epoch, either way: a LEO set
// a week old can be minutes off, and a set much newer than the time it is
// asked about (a rehearsal of an old pass) is as wrong. The limit is the
// operator's (the window keeps it under Element sets); 14 days is where a
// LEO set drifts past what a wide beam forgives.

#include "elementset.h"

#include <QList>
#include <QString>

namespace slew::sky {

inline constexpr double kElementAgeLimitDays = 14.0;
// What an operator may set it to, in the window, the settings and
// --max-element-age alike.
inline constexpr double kLeastElementAgeLimitDays = 0.5;
inline constexpr double kMostElementAgeLimitDays = 365.0;

// Days between the set's epoch and a time, never negative.
double elementAgeDays(const ElementSet &set, double julian);

// Empty when the set may predict at `julian`; otherwise why not, naming the
// time by `when` (e.g. "AOS", "now"): "its elements are 3240.2 days from AOS
// (epoch 2018-01-20T…Z); the limit is 14 days".
QString elementsTooOld(const ElementSet &set, double julian, double limitDays, const QString &when);

// The sets past the limit at a time.
struct ElementAge {
    const ElementSet *set = nullptr;
    double ageDays = 0;
};
QList<ElementAge> staleElements(const QList<ElementSet> &sets, double julian, double limitDays);

} // namespace slew::sky
