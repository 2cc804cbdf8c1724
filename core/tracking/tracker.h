// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The tracker: follows one planned pass with the session's rotator.
//
// Before AOS it plans the pass (passplanner.h) and moves to the planned AOS
// point early enough for this rotator's speed. During the pass it commands
// where the plan will be one response delay ahead (lead-ahead), but only
// when that is more than the minimum step from what was last sent (a
// deadband: relays do not chatter on tiny updates). After LOS it parks or
// stays. A stop, from anywhere (the window, Space, Esc, a rotctld `S`,
// shutdown), ends tracking at once, as does a lost link or a refused move.
//
// It measures as it goes: the pointing error, as an angle on the sky between
// where the antenna points and where the target is, and the commands sent.
// Its timer keeps the link's clock, so a simulator on a manual clock runs a
// whole pass in moments of test time.

#include "passplanner.h"
#include "session/linktimer.h"

#include <QObject>

#include <functional>

namespace slew::session {
class RotatorSession;
}

namespace slew::tracking {

struct TrackerSettings {
    // How far ahead to command: the rotator's response delay. 0.5 s is what
    // the simulated G-5500 class rotator needs (bench_tracking: of 0, 0.5, 1
    // and 1.5 s, 0.5 s gave the smallest RMS on every pass).
    double leadSeconds = 0.5;
    // The deadband: a new target goes out only when the path has moved this
    // far from the last one sent, on either axis. Relays wear; servos do not.
    double minimumStepDeg = 0.5;
    enum class AfterPass { Park, Stay };
    AfterPass afterPass = AfterPass::Park;
    // Arrive at the AOS point this long before AOS.
    double arriveEarlySeconds = 10.0;
    int tickMs = 200;
};

// The default minimum step for a drive: relays switch power to a motor and
// should switch seldom; a servo loop follows fine steps smoothly. On the 60°
// pass of bench_tracking with the simulator's relay control (on beyond 0.5°,
// off within 0.1°), 2° steps gave 0.63° RMS and 1° steps 0.36°, switching
// once every four seconds.
inline constexpr double kRelayMinimumStepDeg = 1.0;
inline constexpr double kServoMinimumStepDeg = 0.5;

struct TrackingFigures {
    int samples = 0;          // position readings after AOS + the settling time
    double rmsDeg = 0;
    double worstDeg = 0;
    int commands = 0;         // go-tos sent during the pass (pre-positioning not counted)
    double passSeconds = 0;
    double commandsPerSecond() const { return passSeconds > 0 ? commands / passSeconds : 0; }
};

class Tracker : public QObject {
    Q_OBJECT
public:
    enum class State { Idle, Waiting, Tracking, Done };
    Q_ENUM(State)

    // Error figures start this long after AOS: the antenna arrives at the
    // AOS point ahead of time, but the first seconds include the lead.
    static constexpr double kSettleSeconds = 5.0;

    explicit Tracker(session::RotatorSession *session, QObject *parent = nullptr);
    ~Tracker() override;

    void setSettings(const TrackerSettings &settings) { m_settings = settings; }
    const TrackerSettings &settings() const { return m_settings; }

    // Plans `pass` (sky points in seconds from AOS, at `aosJulian`) for
    // `reach` and starts: waiting and pre-positioning, then tracking. `now`
    // gives the station's time as a Julian date. False, with the reason in
    // error(), if there is no plan or no link.
    bool track(const QList<SkyPoint> &pass, double aosJulian, const RotatorReach &reach,
               std::function<double()> now);
    // The same with the plan made beforehand (off the window's thread:
    // passforecast.h), which must be of this pass for this reach.
    bool track(const QList<SkyPoint> &pass, const PassPlan &plan, double aosJulian, const RotatorReach &reach,
               std::function<double()> now);
    void stopTracking(const QString &why);
    // The station's time moved on by itself (a paused rehearsal stepped
    // forward): look at once, rather than at the end of a wait that was
    // planned for the time before (up to 30 s long hours before a pass).
    void lookAgain();

    State state() const { return m_state; }
    // The rotator is the tracker's: moving to the AOS point, or tracking.
    // Hours before a pass it is not yet.
    bool hasRotator() const { return m_state == State::Tracking || (m_state == State::Waiting && m_prepositioned); }
    QString error() const { return m_error; }
    const PassPlan &plan() const { return m_plan; }
    // The target's sky along the pass being waited for or followed.
    const QList<SkyPoint> &skyPoints() const { return m_pass; }
    const TrackingFigures &figures() const { return m_figures; }
    // Seconds from AOS now (negative before it).
    double secondsFromAos() const;
    // Where the target is on the sky now, from the pass.
    SkyPoint targetNow() const;

signals:
    void stateChanged(slew::tracking::Tracker::State state, const QString &why);
    void pointingError(double degrees, double secondsFromAos);
    // A point is due and not sent: no position has been read on this link
    // (`why`, the session's words). Once until a point goes again.
    void heldForPosition(const QString &why);

private:
    void tick();
    void onPosition(double az, double el, bool stale);
    void setState(State state, const QString &why);
    // Path positions at a time (linear between points, the ends held).
    PathPoint pathAt(double seconds) const;
    SkyPoint skyAt(double seconds) const;
    // False when nothing went: refused (tracking stops with the reason), or
    // no position read on this link yet (the next tick tries again).
    bool send(double az, double el, bool duringPass);
    // The azimuth to command for the plan's (mechanical) `azimuth`: itself,
    // or, where the antenna is nearer the same bearing's other angle on an
    // overlap rotator, a waypoint only one angle has (see the .cpp).
    double commandFor(double azimuth) const;
    // Waiting long before the move to the AOS point: the next tick later.
    void sleepUntilDue(double stationSeconds);
    static constexpr double kLongestWaitMs = 30000.0;
    // The last command was a waypoint, not the plan's own azimuth.
    bool onWaypoint() const { return m_lastSent && m_lastCommand && m_lastCommand->first != m_lastSent->first; }

    session::RotatorSession *m_session;
    TrackerSettings m_settings;
    session::LinkTimer m_timer;
    QList<SkyPoint> m_pass;
    PassPlan m_plan;
    RotatorReach m_reach;
    double m_aosJulian = 0;
    std::function<double()> m_now;
    State m_state = State::Idle;
    QString m_error;
    bool m_prepositioned = false;
    bool m_sending = false; // our own commands are not someone else's stop
    bool m_heldForPosition = false; // heldForPosition said, no point sent since
    std::optional<std::pair<double, double>> m_lastSent;    // the plan's position last asked for
    std::optional<std::pair<double, double>> m_lastCommand; // what went on the wire for it
    TrackingFigures m_figures;
    double m_sumSquares = 0;
};

} // namespace slew::tracking
