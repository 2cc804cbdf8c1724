// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A jog from the broker is a lease: the axes turn at the speeds asked for
// as long as the operator's window renews it, and stop by themselves when
// it is not renewed in time (at most a second), so a lost network or a
// window that hangs never leaves a rotator turning. A renewal at the same
// speeds sends nothing to the rotator; a new speed goes out at once.
// Anything else that moves or stops the rotator ends the lease.

#include "session/sessiontypes.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

namespace slew::session {
class RotatorSession;
}

namespace slew::station {

class RemoteJog : public QObject {
    Q_OBJECT
public:
    explicit RemoteJog(session::RotatorSession *session, QObject *parent = nullptr);

    // Turns (or keeps turning) each axis at its speed, degrees a second
    // signed (+ clockwise, up; 0 stops an axis this lease was turning), for
    // `leaseMs` from now. Refused as the session refuses a move.
    session::CommandResult jog(double azSpeed, double elSpeed, int leaseMs);
    // Another command takes over: the lease ends, nothing is sent.
    void release();
    bool isActive() const { return m_lease.isActive(); }

signals:
    // The lease ran out unrenewed and the axes were told to stop.
    void expired(int leaseMs, double azSpeed, double elSpeed);

private:
    void onExpired();
    session::CommandResult turn(session::Axis axis, double speed, double &current);

    session::RotatorSession *m_session;
    QTimer m_lease;
    double m_azSpeed = 0, m_elSpeed = 0; // what the axes were sent; 0 when not jogging
    int m_leaseMs = 0;
    bool m_turning = false; // jog() is sending: its own stops end no lease
};

} // namespace slew::station
