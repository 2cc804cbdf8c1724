#include "sampleclock.h"

#include "session/rotatorsession.h"
#include "transport/link.h"

namespace slew::tuning {

SampleClock::SampleClock(const session::RotatorSession *session) : m_session(session)
{
    m_wall.start();
}

double SampleClock::now() const
{
    // Asked every time: the session may have reconnected to another link.
    if (m_session && m_session->link()) {
        if (const std::optional<double> linkClock = m_session->link()->clockSeconds())
            return *linkClock;
    }
    return double(m_wall.nsecsElapsed()) / 1e9;
}

} // namespace slew::tuning
