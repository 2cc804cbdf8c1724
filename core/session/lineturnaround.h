// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The pause a half-duplex line needs between the controller's reply and
// the next line to it. On RS485 the controller drives the pair while it
// answers and lets go of it only some time after its last byte (the SatNOGS
// firmware: about 9 ms); a line sent before then is lost, and a move lost
// that way is a move that never happened. So a line written within that
// time of the last byte received is held until it is over; and a line
// written while a request waits for its answer (a move or a stop beside a
// poll) is held until the answer is in and the pause is over, or at most
// kLongestHoldMs (a controller that does not answer never takes the line).
// Held lines leave in the order written, each request waiting for its
// answer before the next line goes.
//
// Times are the link's milliseconds (LinkTimer), so a manual-clock
// simulator paces the pause as it paces everything else.

#include "linktimer.h"

#include <QByteArray>
#include <QObject>

#include <deque>

namespace slew::session {

class LineTurnaround : public QObject {
    Q_OBJECT
public:
    static constexpr int kLongestHoldMs = 100;

    explicit LineTurnaround(QObject *parent = nullptr);

    // 0: a full-duplex line, nothing is held.
    void setTurnaroundMs(int ms) { m_turnaroundMs = ms; }
    void followClockOf(transport::Link *link) { m_timer.followClockOf(link); }

    void noteReceived(qint64 nowMs) { m_lastReceivedMs = nowMs; }
    // True when `bytes` were held, to leave by released(); false when they
    // may be written now. A request expects an answer (replyEnded()).
    bool hold(const QByteArray &bytes, bool request, qint64 nowMs);
    // The request written last has its answer, or has given up on it.
    void replyEnded(qint64 nowMs);
    // A link that closed: what was held is not for the next one.
    void clear();
    // Lines wait to be written.
    bool holding() const { return !m_held.empty(); }

signals:
    void released(const QByteArray &bytes);
    // The last line held has been released (or dropped with the link).
    void drained();

private:
    struct Held {
        QByteArray bytes;
        bool request;
    };
    void scheduleRelease(qint64 nowMs);
    void releaseDue();

    int m_turnaroundMs = 0;
    bool m_awaitingReply = false;
    qint64 m_lastReceivedMs = -1'000'000;
    std::deque<Held> m_held;
    LinkTimer m_timer;
};

} // namespace slew::session
