#include "sampleclock.h"

#include "session/rotatorsession.h"
#include "sim/simulator.h"
#include "sim/simulatorscheme.h"

namespace slew::tuning {

SampleClock::SampleClock(const session::RotatorSession *session) : m_session(session)
{
    m_wall.start();
}

double SampleClock::now() const
{
    // Asked every time: the session may have reconnected to another link.
    if (m_session) {
        if (sim::Simulator *sim = sim::simulatorBehind(m_session->link()))
            return sim->clock().now();
    }
    return double(m_wall.nsecsElapsed()) / 1e9;
}

} // namespace slew::tuning
