// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A timer that keeps the link's time. On hardware, and on a simulator that
// runs by the wall clock, it is a QTimer. On a link whose clock is stepped
// (a manual-clock simulator in tests) it fires when that clock passes the
// deadline, so polling, reply timeouts and the stop hold happen at the same
// simulated moments however fast or busy the machine is.
//
// The session's timers that pace the conversation with the rotator use it;
// the reconnect timer does not, as there is no link to keep time then.

#include <QObject>
#include <QPointer>
#include <QTimer>

#include <optional>

namespace slew::transport {
class Link;
}

namespace slew::session {

class LinkTimer : public QObject {
    Q_OBJECT
public:
    explicit LinkTimer(QObject *parent = nullptr);

    void setSingleShot(bool singleShot);
    void setInterval(int ms);
    int interval() const { return m_intervalMs; }

    void start();
    void start(int ms);
    void stop();
    bool isActive() const;

    // Keep time by this link's clock when it is stepped, else by the wall
    // clock (also with null). A running timer starts its interval afresh.
    void followClockOf(transport::Link *link);

signals:
    void timeout();

private:
    double linkNow() const;
    void onClockStepped();
    void fireIfDue();

    QTimer m_wall;
    QPointer<transport::Link> m_stepped; // set only while its clock is stepped
    QMetaObject::Connection m_steps;
    int m_intervalMs = 0;
    bool m_singleShot = false;
    std::optional<double> m_deadline; // in link seconds, while running on a stepped clock
    bool m_checkQueued = false;
};

} // namespace slew::session
