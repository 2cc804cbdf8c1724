#pragma once
// The time base position samples are stamped with. Against real hardware it
// is a monotonic wall clock; against the simulator it is the simulator's own
// clock, so a test that steps simulated time gets exact, repeatable figures
// however fast or slow the machine running it is.

#include <QElapsedTimer>

namespace slew::session {
class RotatorSession;
}

namespace slew::tuning {

class SampleClock {
public:
    explicit SampleClock(const session::RotatorSession *session);

    // Seconds on a clock that only moves forward.
    double now() const;

private:
    const session::RotatorSession *m_session;
    QElapsedTimer m_wall;
};

} // namespace slew::tuning
