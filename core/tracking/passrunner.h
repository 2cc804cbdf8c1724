// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Tracks every pass of one target, one after another, until told to stop:
// the station service's `--track`. For each pass it predicts the next one
// from the station clock and plans it (on a worker thread: the moon takes
// a good part of a second), hands it to the Tracker, and logs the
// plan, AOS, and at LOS the pointing figures. A stop from anywhere ends it
// for good; a lost link ends the pass, and the next pass is planned once
// the link is back.

#include "passforecast.h"
#include "stationclock.h"
#include "tracker.h"
#include "tracktarget.h"

#include "sky/sgp4.h"
#include "sky/site.h"
#include "sky/sunmoon.h"
#include "sky/elementage.h"
#include "sky/elementsetformat.h"

#include <QObject>
#include <QTimer>

#include <atomic>
#include <functional>
#include <memory>
#include <optional>

namespace slew::tracking {

class PassRunner : public QObject {
    Q_OBJECT
public:
    explicit PassRunner(session::RotatorSession *session, QObject *parent = nullptr);
    ~PassRunner() override;

    // What to do after LOS. The lead, the minimum step and the rotator's
    // reach come from the session's profile as each pass is planned
    // (rotatorreach.h), so a profile changed between passes applies to the next.
    void setAfterPass(TrackerSettings::AfterPass afterPass) { m_afterPass = afterPass; }
    // A satellite's pass whose AOS is further than this from its elements'
    // epoch is not tracked (sky/elementage.h).
    void setElementAgeLimitDays(double days) { m_elementAgeLimitDays = days; }
    double elementAgeLimitDays() const { return m_elementAgeLimitDays; }
    // Who else is steering the rotator now (a remote tracker on the rotctld
    // port), or empty. A pass does not start while someone does: the two
    // would fight over the rotator.
    void setOtherSteering(std::function<QString()> who) { m_otherSteering = std::move(who); }
    // Starts with the next pass (or the one in progress). The clock must
    // outlive the runner. When the clock is changed (started again, another
    // rate, real time) the runner starts afresh as it would for a new
    // target: the pass it was on was planned for another time.
    void start(const TrackTarget &target, const sky::Site &station, double minElevationDeg,
               const StationClock *clock);
    // One pass only, the schedule's (schedule/schedule.h): the pass of
    // `target` between `fromJulian` and `untilJulian`, or the stretch of a
    // long target (the sun, a fixed direction) between them; then it stops
    // and says onePassEnded(). A lost link pauses it as ever; a changed
    // clock ends it (the schedule plans again).
    void startOne(const TrackTarget &target, const sky::Site &station, double minElevationDeg,
                  const StationClock *clock, double fromJulian, double untilJulian);
    void stop(const QString &why);

    bool isRunning() const { return m_running; }
    // A pass is being waited for or tracked.
    bool isActive() const;
    // The rotator is the tracker's (moving to the AOS point, or tracking):
    // remote trackers are held off.
    bool holdsRotator() const { return m_tracker.hasRotator(); }
    const Tracker &tracker() const { return m_tracker; }
    // What is tracked and from where, as start() was told.
    const TrackTarget &target() const { return m_target; }
    const sky::Site &station() const { return m_station; }
    int passesDone() const { return m_passesDone; }
    // The pass handed to the tracker last (its AOS, TCA and LOS as
    // predicted), so what is recorded of it has its times and a station can
    // publish it; none before, and none after stop().
    const std::optional<sky::Pass> &pass() const { return m_pass; }

    // How one pass of startOne() ended.
    enum class OneEnd {
        Tracked,      // to its LOS, or the end of its stretch
        NotFound,     // no such pass (any more) between the times given
        Stopped,      // a stop from anywhere, a refused point, stop()
        ClockChanged, // the station clock was started again or changed rate
    };
    Q_ENUM(OneEnd)

signals:
    void logLine(const QString &line);
    void onePassEnded(slew::tracking::PassRunner::OneEnd end, const QString &why);
    // holdsRotator() changed.
    void activeChanged(bool holdsRotator);

private:
    void begin(const TrackTarget &target, const sky::Site &station, double minElevationDeg,
               const StationClock *clock);
    void endOne(OneEnd end, const QString &why);
    void nextPass();
    void startAfresh(const QString &why);
    void onPlanned(const std::optional<PlannedPass> &next, const RotatorReach &reach, double plannedAtJulian);
    void onTrackerState(Tracker::State state, const QString &why);
    // Plans again a second after the pass's LOS (at most an hour on).
    void retryAfter(const sky::Pass &pass, double plannedAtJulian);
    static QString isoTime(double julian);

    session::RotatorSession *m_session;
    Tracker m_tracker;
    TrackTarget m_target;
    std::optional<TargetSky> m_sky;
    std::optional<sky::Pass> m_pass;
    sky::Site m_station;
    double m_minElevation = 0;
    double m_elementAgeLimitDays = sky::kElementAgeLimitDays;
    TrackerSettings::AfterPass m_afterPass = TrackerSettings::AfterPass::Park;
    std::function<QString()> m_otherSteering;
    QString m_waitingFor; // the other tracker a pass is waiting on, if any
    const StationClock *m_clock = nullptr;
    QMetaObject::Connection m_clockChanged;
    QMetaObject::Connection m_clockStepped;
    bool m_running = false;
    bool m_planning = false;
    int m_generation = 0; // a plan still being made when this moves on is of no use
    // Tells the worker making the current plan to give up: a stop or a new
    // target must not wait for a search of days ahead, nor must the exit.
    std::shared_ptr<std::atomic<bool>> m_planStop;
    void cancelPlanning();
    bool m_wasActive = false;
    int m_passesDone = 0;
    QTimer m_retry; // no pass found: look again later
    // startOne()'s times; none for start()'s every pass.
    std::optional<std::pair<double, double>> m_one;
};

} // namespace slew::tracking
