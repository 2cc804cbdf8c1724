#include "sampleclock.h"

#include "session/rotatorsession.h"
#include "transport/link.h"

#include <QObject>

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

QString fasterThanRealTime(const session::RotatorSession *session)
{
    const transport::Link *link = session ? session->link() : nullptr;
    const double scale = link ? link->timeScale() : 1.0;
    if (scale <= 1.0)
        return {};
    // Reads a second of the simulator's own time. slew --tune polls at 50 Hz
    // and measures at 4x what it measures at 1x (tst_slewtune); the window
    // polls at the profile's pace, a few reads a step at a rehearsal's 5x.
    const double reads = session->profile().pollHz / scale;
    if (reads >= kLeastReadsPerSimulatedSecond)
        return {};
    return QObject::tr("the simulator runs %1 times faster than real time, with a rehearsal's station clock: its "
                       "position is read at the usual pace, so a step would get %1 times fewer samples than it needs. "
                       "Put the station clock back to real time to measure")
        .arg(scale, 0, 'g', 3);
}

} // namespace slew::tuning
