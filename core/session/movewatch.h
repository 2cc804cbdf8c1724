// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Follows one move to its end and says once how it ended: arrived (come to
// rest within kArrivedDegrees of the target, or within the controller's own
// tolerance where it is wider: protocol/firmware.h), stopped short (came to rest
// elsewhere after moving: a limit, an obstacle, a stop from another client),
// stopped (a stop went out through this session), replaced (another target
// was sent), refused (the controller answered the move with its "no") or
// the link went down. slewctl's --wait and the window's status
// lines and event log judge arrival the same way through it.

#include <QObject>
#include <QPointF>
#include <QString>

#include <optional>

namespace slew::session {

class RotatorSession;

class MoveWatch : public QObject {
    Q_OBJECT
public:
    enum class Outcome { Arrived, StoppedShort, Stopped, Replaced, Refused, LinkLost };
    Q_ENUM(Outcome)

    // Both axes this close to the target, at rest, is arrival. Passing
    // through on the way in is not (a G-5500 still moves a degree in a few
    // tenths of a second after it is told to stop).
    static constexpr double kArrivedDegrees = 1.0;

    explicit MoveWatch(RotatorSession *session, QObject *parent = nullptr);

    // A move to target (pointing frame) has just been sent. Without a target
    // (a park position not read yet) the move ends where the rotator comes
    // to rest after moving, reported as arrived.
    void watch(std::optional<QPointF> target);
    void cancel(); // forget it, report nothing
    bool isWatching() const { return m_watching; }
    std::optional<QPointF> target() const { return m_target; }
    // Why the controller refused the move, after Outcome::Refused.
    QString refusal() const { return m_refusal; }

signals:
    // Once per watch. `at` is the position when it ended; `offDeg` the larger
    // axis' distance from the target (0 without a target).
    void ended(slew::session::MoveWatch::Outcome outcome, QPointF at, double offDeg);

private:
    void onPosition(double az, double el, bool stale);
    void finish(Outcome outcome);
    double offTarget(QPointF at) const;
    bool arrived(QPointF at) const; // at rest here, a move to m_target has arrived

    RotatorSession *m_session;
    bool m_watching = false;
    std::optional<QPointF> m_target;
    std::optional<QPointF> m_start; // where the rotator stood when the move went out
    std::optional<QPointF> m_last;
    int m_steadyPolls = 0;
    bool m_sawMotion = false;
    QString m_refusal;
};

} // namespace slew::session
