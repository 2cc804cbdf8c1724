// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One element set propagated at many times in a row: a pass scan, a pass
// sampled for the planner, the position every tick. For the resonant
// deep-space orbits (12-hour Molniya, 24-hour geosynchronous) Sgp4 integrates
// half a day at a time from epoch; this keeps the last point reached and goes
// on from there, the way the reference code carries its integrator between
// calls, and with the same states as starting from epoch every time (the
// points do not depend on what was asked before; see Sgp4::integrateResonance).
// Times that go on away from epoch cost a step now and then; a time nearer
// to epoch than the last point, or on its other side, starts again.
//
// The Sgp4 stays const and may be shared between threads; a propagator is
// the caller's, for one thread at a time, and must not outlive the Sgp4.

#include "sgp4.h"

namespace slew::sky {

class Sgp4Propagator {
public:
    explicit Sgp4Propagator(const Sgp4 &satellite) : m_satellite(&satellite) {}

    Sgp4State propagate(double minutesSinceEpoch) { return m_satellite->propagate(minutesSinceEpoch, m_carried); }
    Sgp4State propagateToJulian(double julianDate)
    {
        return propagate(m_satellite->minutesSinceEpoch(julianDate));
    }
    const Sgp4 &satellite() const { return *m_satellite; }

private:
    const Sgp4 *m_satellite;
    Sgp4::ResonancePoint m_carried; // time 0: nothing carried yet
};

} // namespace slew::sky
