// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A rehearsal on the built-in simulator keeps one pace: while the station
// clock runs N times faster than real time, so does the simulator's clock,
// and with it the rotator, so the antenna keeps up with a plan made by the
// station clock. A new rate applies to the running simulator from where it
// is: the rotator carries on from its position, with no reconnect and no
// jump. A simulator connected during a rehearsal takes the rate as it
// connects. Back in real time the simulator runs at real time too.
//
// Hardware, and a simulator on a manual clock (tests), keep their own pace;
// follows() says which the session's link does.

#include <QObject>

namespace slew::session {
class RotatorSession;
}

namespace slew::tracking {

class StationClock;

class SimulatorPace : public QObject {
    Q_OBJECT
public:
    // Both must outlive this.
    SimulatorPace(session::RotatorSession *session, const StationClock *clock, QObject *parent = nullptr);

    // The session's link runs at the station clock's rate: the link is a
    // wall-clock simulator and the rate was last given to it.
    bool follows() const { return m_follows; }

signals:
    void followsChanged(bool follows);

private:
    void pace();
    void setFollows(bool follows);

    session::RotatorSession *m_session;
    const StationClock *m_clock;
    bool m_follows = false;
};

} // namespace slew::tracking
