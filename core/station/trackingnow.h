// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What Slew's own tracking is doing now, in one set of words for every
// face: the window's line beside STOP, the state a station publishes
// (statepublisher.h), a remote window's readout.

#include "sky/passes.h"

#include <QString>

#include <optional>

namespace slew::tracking {
class PassRunner;
}

namespace slew::station {

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

// Read off the pass runner (none: off).
TrackingNow trackingNow(const tracking::PassRunner *runner);

// The phase as the station's published state spells it: "off", "planning",
// "waiting", "tracking", "done".
QString phaseWord(TrackingNow::Phase phase);
// The phase a word names; none for a word that names none.
std::optional<TrackingNow::Phase> phaseFromWord(const QString &word);

} // namespace slew::station
