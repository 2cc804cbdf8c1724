// SPDX-License-Identifier: GPL-3.0-or-later
#include "simulatorpace.h"

#include "stationclock.h"

#include "session/rotatorsession.h"
#include "transport/link.h"

namespace slew::tracking {

using session::RotatorSession;

SimulatorPace::SimulatorPace(RotatorSession *session, const StationClock *clock, QObject *parent)
    : QObject(parent), m_session(session), m_clock(clock)
{
    connect(clock, &StationClock::changed, this, &SimulatorPace::pace);
    connect(session, &RotatorSession::stateChanged, this, [this](RotatorSession::State state) {
        if (state == RotatorSession::State::Connected) {
            // Outside a rehearsal a new link keeps the pace its URI asked
            // for (`sim:?time_scale=5`): nobody asked for another.
            if (m_clock->isRehearsal())
                pace();
            else
                setFollows(false);
        } else if (state == RotatorSession::State::Disconnected) {
            setFollows(false);
        }
    });
    if (clock->isRehearsal())
        pace();
}

void SimulatorPace::pace()
{
    transport::Link *link = m_session->link();
    setFollows(link && link->setTimeScale(m_clock->rate()));
}

void SimulatorPace::setFollows(bool follows)
{
    if (follows == m_follows)
        return;
    m_follows = follows;
    emit followsChanged(follows);
}

} // namespace slew::tracking
