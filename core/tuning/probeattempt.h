// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What BaudProbe and DialectIdentifier share: a run of attempts, each on a
// session of its own (one URI, one dialect) with a time limit. An attempt
// ends once, by its owner's verdict or by the time limit; its session is
// closed and deleted from the event loop, since the owner may be inside one
// of the session's signals when it decides.

#include "protocol/dialect.h"

#include <QObject>
#include <QTimer>

#include <functional>
#include <memory>

namespace slew::session {
class RotatorSession;
}

namespace slew::tuning {

class ProbeAttempt {
public:
    // owner receives the session's signals the caller connects, and the
    // time limit: timedOut is called when it passes.
    ProbeAttempt(QObject *owner, int limitMs, std::function<void()> timedOut);
    ~ProbeAttempt();

    void setLimitMs(int ms) { m_timer.setInterval(ms); }
    int limitMs() const { return m_timer.interval(); }

    // A fresh session for uri in dialect, not yet connected: connect its
    // signals, then call go().
    session::RotatorSession *begin(protocol::Dialect dialect);
    void go(const QString &uri);
    // The session of the attempt under way; null between attempts.
    session::RotatorSession *session() const { return m_session.get(); }
    bool isRunning() const { return m_session != nullptr; }
    // Ends the attempt: no more signals to the owner, the link closed, the
    // session deleted later. Safe to call twice, or with none under way.
    void end();

private:
    QObject *m_owner;
    std::unique_ptr<session::RotatorSession> m_session;
    QTimer m_timer;
};

} // namespace slew::tuning
