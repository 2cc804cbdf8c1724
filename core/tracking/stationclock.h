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
//
// A rehearsal can also be paused: the clock holds the instant it reads and
// steps forward only when told. A pause, a resume and a step do not make
// anyone plan again (pausedChanged(), stepped(), not changed()): the time
// goes on from where it was, so a plan made before still holds, and a
// tracker that reads the clock at each tick simply holds its point, or
// moves on to the point the step reaches (past the LOS, the pass ends).

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
    // The rate it runs at when not paused.
    double rate() const { return m_rate; }
    bool isPaused() const { return m_heldAt.has_value(); }

    // From now on the clock reads `startJulian` and runs `rate` (1 to
    // kMaxRate) times faster than real time; a pause ends.
    void rehearse(double startJulian, double rate);
    // A rehearsal goes on from the instant it reads now at another rate:
    // the clock does not jump, and a paused one stays paused. Ignored in
    // real time.
    void setRate(double rate);
    // Back to the system's UTC; a pause ends.
    void followRealTime();

    // While paused: holds `julian` instead, still paused, as one change
    // (a jump of the window's slider). False, and nothing changes, when
    // running (rehearse() moves a running clock) or for no number.
    bool holdAt(double julian);
    // Holds the instant it reads now. In real time that makes it a
    // rehearsal from now (the clock no longer follows the system's UTC).
    void pause();
    // Runs on at its rate from the instant it held.
    void resume();
    // While paused: forward by `seconds` (more than 0) and still paused.
    // False, and nothing changes, when running or for no time forward.
    bool step(double seconds);

signals:
    // Started again, a new rate, or back to real time: plan again.
    void changed();
    // Paused or running on, from the same instant.
    void pausedChanged(bool paused);
    // Moved forward while paused (step()).
    void stepped();

private:
    std::optional<double> m_start;
    double m_rate = 1.0;
    QElapsedTimer m_elapsed;
    std::optional<double> m_heldAt; // the instant a pause holds
};

} // namespace slew::tracking
