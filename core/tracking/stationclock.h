// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The station's time for tracking: the system's UTC, or a rehearsal clock
// that starts at a chosen instant (`--clock-start`, the window's Time
// controller) and runs at real rate, or faster to keep pace with a
// time-scaled simulator (`--clock-rate`).
//
// The window changes it while it runs (a new start, a new rate, back to
// real time); changed() tells whoever planned by it, so the pass table and
// a running tracker plan again rather than follow a plan made for another
// time.

#include <QElapsedTimer>
#include <QObject>

#include <optional>

namespace slew::tracking {

class StationClock : public QObject {
    Q_OBJECT
public:
    // The fastest a rehearsal runs: the simulator's fastest time scale
    // (sim::SimClock::maxTimeScale), so the two can keep pace.
    static constexpr double kMaxRate = 20.0;

    // No start: the system's UTC. A rate other than 1 needs a start.
    explicit StationClock(std::optional<double> startJulian = std::nullopt, double rate = 1.0,
                          QObject *parent = nullptr);

    double nowJulian() const;
    bool isRehearsal() const { return m_start.has_value(); }
    double rate() const { return m_rate; }

    // From now on the clock reads `startJulian` and runs `rate` (1 to
    // kMaxRate) times faster than real time.
    void rehearse(double startJulian, double rate);
    // A rehearsal goes on from the instant it reads now at another rate:
    // the clock does not jump. Ignored in real time.
    void setRate(double rate);
    // Back to the system's UTC.
    void followRealTime();

signals:
    // Started again, a new rate, or back to real time.
    void changed();

private:
    std::optional<double> m_start;
    double m_rate = 1.0;
    QElapsedTimer m_elapsed;
};

} // namespace slew::tracking
