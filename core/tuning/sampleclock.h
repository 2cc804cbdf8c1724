#pragma once
// The time base position samples are stamped with. Against real hardware it
// is a monotonic wall clock; against the simulator it is the simulator's own
// clock, so a test that steps simulated time gets exact, repeatable figures
// however fast or slow the machine running it is.

#include <QElapsedTimer>
#include <QString>

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

// Why a step cannot be measured on the session's link now, in the
// operator's words, or empty. A simulator run faster than real time (paced
// to a rehearsal's station clock) moves that many times further between
// two position reads, which keep the wall clock's pace: a step gets a few
// samples, too few to fit gains or measure a speed by, and the figures
// would be offered as if they were good.
// It is said when the reads come fewer than kLeastReadsPerSimulatedSecond
// to a second of the simulator's time.
inline constexpr double kLeastReadsPerSimulatedSecond = 10.0;
QString fasterThanRealTime(const session::RotatorSession *session);

} // namespace slew::tuning
