// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How often the session polls the rotator. A station spends most of its
// life with the antenna parked and nobody steering; polling it ten times a
// second then only wakes the machine (a Raspberry Pi, day and night) to
// learn that nothing changed. So: the full rate while anything happens, and
// a slow one (the profile's restPollHz) once nothing has moved and nobody
// has steered for kQuietMs. A tracker that only reads the position leaves
// it slow (bridge/rotctldserver.cpp, wakesPolling, says why that is fresh
// enough).
//
// It decides only; the session tells it what happened (a command, a tracker
// steering, an alarm, a position) and asks it for the interval at each poll.
// Times are the link's milliseconds, so a manual-clock simulator paces it
// as it paces everything else.

#include <QtGlobal>

#include <cmath>

namespace slew::session {

class PollPace {
public:
    // Nothing moved and nobody steered for this long: the slow rate. Longer
    // than any settling a tool counts in polls (a move is "at rest" after
    // three steady polls, a tuning step after a second).
    static constexpr qint64 kQuietMs = 5000;
    // Farther than this from where the rotator last stood still is motion:
    // above encoder jitter and the replies' rounding, far below anything an
    // operator would miss for a second.
    static constexpr double kMovedDegrees = 0.05;

    void setIntervals(int fullMs, int restMs);
    int fullMs() const { return m_fullMs; }
    int restMs() const { return m_restMs; }

    // A command, a tracker steering, an alarm: the full rate from now.
    void wake(qint64 nowMs);
    // A fresh position. One that moved from where the rotator last stood
    // wakes; drift too slow to see from poll to poll adds up until it does.
    void notePosition(double az, double el, qint64 nowMs);
    // A new link: nothing known of where the rotator stands, full rate.
    void restart(qint64 nowMs);

    bool resting(qint64 nowMs) const { return nowMs - m_lastWakeMs >= kQuietMs; }
    int intervalMs(qint64 nowMs) const { return resting(nowMs) ? m_restMs : m_fullMs; }

private:
    int m_fullMs = 100;
    int m_restMs = 1000;
    qint64 m_lastWakeMs = 0;
    double m_stillAz = NAN, m_stillEl = NAN; // where the rotator last stood still
};

} // namespace slew::session
