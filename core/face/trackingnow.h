// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What Slew's own tracking is doing now, in one set of words for every
// face: the window's line beside STOP, the state a station publishes
// (face/stationstate.h's tracking fields), a remote window's readout. A
// station in this process reads it off its pass runner
// (station/trackingnow.h); any face reads it off a state (trackingOf).

#include "face/stationstate.h"
#include "sky/passes.h"

#include <QString>

#include <optional>

namespace slew::face {

struct TrackingNow {
    enum class Phase {
        Off,      // no tracking
        Planning, // finding the next pass
        Waiting,  // a pass planned, not begun (or the antenna on its way to the AOS point)
        Tracking, // following the target
        Done,     // a pass just ended; the next one is being found
    };
    Phase phase = Phase::Off;
    QString target;           // as the runner names it: "FOX-1B (AO-91)", "Sun"
    std::optional<int> norad; // a satellite's catalogue number
    std::optional<sky::Pass> pass; // the pass waited for or followed
};

// The phase as a station's state spells it: "off", "planning", "waiting",
// "tracking", "done".
QString phaseWord(TrackingNow::Phase phase);
// The phase a word names; none for a word that names none.
std::optional<TrackingNow::Phase> phaseFromWord(const QString &word);

// What a state says of the tracking: the phase, the target, and the pass's
// AOS and LOS (to the millisecond the state carries them).
TrackingNow trackingOf(const StationState &state);

// A station's time as a Julian date, from Unix milliseconds (its state's
// clock, stationClockMs), and back.
double julianOfUnixMs(qint64 ms);
qint64 unixMsOfJulian(double julian);

} // namespace slew::face
