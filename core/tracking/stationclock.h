// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The station's time for tracking: the system's UTC, or a rehearsal clock
// that starts at a chosen instant (`--clock-start`) and runs at real rate,
// or faster to keep pace with a time-scaled simulator (`--clock-rate`).

#include <QElapsedTimer>

#include <optional>

namespace slew::tracking {

class StationClock {
public:
    // No start: the system's UTC. A rate other than 1 needs a start.
    explicit StationClock(std::optional<double> startJulian = std::nullopt, double rate = 1.0);

    double nowJulian() const;
    bool isRehearsal() const { return m_start.has_value(); }
    double rate() const { return m_rate; }

private:
    std::optional<double> m_start;
    double m_rate;
    QElapsedTimer m_elapsed;
};

} // namespace slew::tracking
