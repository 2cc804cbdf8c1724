// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Runs the station's schedule (schedule/schedule.h): several targets in
// priority order, followed pass after pass with the station's pass runner,
// each pass as the plan took it, without anyone choosing at each AOS.
//
//   - It plans the next hours on a worker thread from the station's clock,
//     place, horizon and rotator (its speeds, and where the antenna
//     stands), logs every decision, and follows the taken passes in turn:
//     one PassRunner::startOne() each. Between two passes close together
//     the antenna stays where the first left it; with time to spare, it
//     parks.
//   - It plans again when the element sets are refreshed, the targets
//     change (added, removed, reordered), the clock is changed, and when
//     half of the planned window has gone by. A pass in progress is kept
//     through a new plan (it is pinned), and if its target is no longer in
//     the list that is said: it still ends at its LOS, not before.
//   - A stop from anywhere (the operator's Stop, a rotctld `S`, untrack)
//     ends the schedule, as it ends tracking.
//   - A pass the plan dropped is said (passDropped) once its time has come,
//     for the station's record.

#include "schedule/schedule.h"
#include "tracking/passrunner.h"
#include "tracking/tracktarget.h"

#include "sky/site.h"
#include "sky/elementsetformat.h"

#include <QObject>
#include <QSet>
#include <QTimer>

#include <atomic>
#include <memory>
#include <optional>

namespace slew::session {
class RotatorSession;
}
namespace slew::tracking {
class StationClock;
}

namespace slew::station {

struct ScheduleOptions {
    double minElevationDeg = 0;
    double hours = 24;
    double guardSeconds = 30;
    // The elements' age limit is the pass runner's, one for one target and
    // the schedule (PassRunner::setElementAgeLimitDays).

    friend bool operator==(const ScheduleOptions &, const ScheduleOptions &) = default;
};

// Why a schedule may not be run (or previewed) with these options, or
// empty: the ranges every face takes (face/schedulerequest.h), so one in
// this process is held to what the broker's commands are.
QString scheduleOptionsFault(const ScheduleOptions &options);

// The settings a plan made now is made with: from the station's clock, the
// options, the pass runner's element age limit, and where the antenna
// stands. One for the schedule run and its preview, so a preview is the
// plan the run would make.
schedule::ScheduleSettings scheduleSettingsNow(const session::RotatorSession &session,
                                               const tracking::PassRunner &runner,
                                               const tracking::StationClock &clock, const ScheduleOptions &options);

class ScheduleRunner : public QObject {
    Q_OBJECT
public:
    // All three must outlive this.
    ScheduleRunner(session::RotatorSession *session, tracking::PassRunner *runner,
                   const tracking::StationClock *clock, QObject *parent = nullptr);
    ~ScheduleRunner() override;

    // Plans and runs. The targets are in priority order, the first highest.
    void start(const QList<tracking::TrackTarget> &targets, const sky::Site &place, const ScheduleOptions &options);
    void stop(const QString &why);
    bool isRunning() const { return m_running; }

    // A new list (an added target, a new order): planned again at once.
    void setTargets(const QList<tracking::TrackTarget> &targets);
    const QList<tracking::TrackTarget> &targets() const { return m_targets; }
    const ScheduleOptions &options() const { return m_options; }
    // The target of that name in the list, if it is still there.
    std::optional<tracking::TrackTarget> targetNamed(const QString &name) const;
    // Refreshed element sets: each satellite target takes its newest set
    // (by catalogue number), and the schedule is planned again.
    void updateElements(const QList<sky::ElementSet> &sets);

    const schedule::Schedule &schedule() const { return m_schedule; }
    bool isPlanning() const { return m_planning; }
    // The taken pass being waited for or followed now.
    const std::optional<schedule::ScheduledPass> &current() const { return m_current; }

signals:
    void logLine(const QString &line);
    void runningChanged(bool running);
    void scheduleChanged();
    void currentChanged();
    // A pass the plan dropped, once its AOS has come.
    void passDropped(const slew::schedule::ScheduledPass &pass);

private:
    void plan(const QString &why);
    void onPlanned(const schedule::Schedule &made, const QString &why);
    void advance();
    void onOneEnded(tracking::PassRunner::OneEnd end, const QString &why);
    void sayDroppedUpTo(double julian);
    void armTimer();
    std::optional<schedule::ScheduledPass> nextTaken(double nowJulian) const;
    QString keyOf(const schedule::ScheduledPass &pass) const;
    void cancelPlanning();

    session::RotatorSession *m_session;
    tracking::PassRunner *m_runner;
    const tracking::StationClock *m_clock;
    QList<tracking::TrackTarget> m_targets;
    sky::Site m_place;
    ScheduleOptions m_options;
    schedule::Schedule m_schedule;
    std::optional<schedule::ScheduledPass> m_current;
    bool m_running = false;
    bool m_planning = false;
    bool m_planAgain = false; // asked while a plan was being made
    QString m_planAgainWhy;
    double m_doneUntil = 0;     // the end of the last pass followed (or let go)
    QSet<QString> m_saidDropped; // passes dropped and said, by target and start
    int m_generation = 0;
    std::shared_ptr<std::atomic<bool>> m_planStop;
    QTimer m_wake; // the next thing to do: plan again, or say a dropped pass
    QMetaObject::Connection m_clockChanged;
};

} // namespace slew::station
