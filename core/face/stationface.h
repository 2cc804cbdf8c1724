// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A station as every face sees it, whether it runs in this process or on a
// broker: its state, plan, schedule and telemetry as values, and the
// operator's intents, each answered with one Outcome (outcome.h). The
// window shows a station through this, and only through this; what only a
// link in this process has (the register editor, raw traffic, the wizard)
// is behind the local window's own door, not here.
//
// Two kinds implement it: the station this process runs
// (station/localstationface.h, the operator at the station) and one on a
// broker (remote/remotestation.h, an operator elsewhere, under the
// station's rules for remote control: its holds, the jog's lease, its gate).
// The same intent is refused for the same reason in the same words by
// both, since the station's own parts judge it in both cases.

#include "face/outcome.h"
#include "face/schedulepreview.h"
#include "face/schedulerequest.h"
#include "face/stationplan.h"
#include "face/stationschedule.h"
#include "face/stationstate.h"
#include "face/telemetrysample.h"

#include "model/movegate.h"

#include <QObject>
#include <QStringList>

#include <optional>

namespace slew::face {

class StationFace : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;

    // --- State ---------------------------------------------------------------
    // How the face names the station: "mast" on a broker; the link's URI here.
    virtual QString title() const = 0;
    // The station runs in this process (the local-only door may open).
    virtual bool isLocal() const = 0;
    // What is shown is the station as it is now: always, in this process;
    // from afar, while the broker and the station are there and the last
    // state is recent. A face greys its controls (not Stop) when it is not.
    virtual bool isLive() const = 0;
    // Why it is not live, in words; empty when it is.
    virtual QString whyNotLive() const = 0;
    // What is known now; none before the first word from a remote station.
    virtual std::optional<StationState> state() const = 0;
    virtual std::optional<StationPlan> plan() const = 0;
    virtual std::optional<StationSchedule> schedule() const = 0;
    // The station's clock now, in Unix milliseconds: the wall clock, or a
    // rehearsal's time. A face counts down by it. None before a remote
    // station's first state.
    virtual std::optional<qint64> stationClockMs() const = 0;
    // What the station's gate would say to a go-to, for fields checked as
    // the operator types. The station's own gate has the last word.
    virtual model::MoveCheck previewPointing(double az, double el) const = 0;

    // --- Intent --------------------------------------------------------------
    virtual Outcome gotoPosition(double az, double el) = 0;
    // Always sent when there is a way to send it. `cause` (the key, the
    // button) goes to the station's log.
    virtual Outcome stop(const QString &cause) = 0;
    virtual Outcome park() = 0;
    virtual Outcome home() = 0;
    // Follows every pass of a target above `minElevationDeg`: a satellite
    // by its name or catalogue number, "sun", "moon", or "az,el".
    virtual Outcome track(const QString &target, double minElevationDeg) = 0;
    // Ends the schedule and one target's tracking alike.
    virtual Outcome untrack() = 0;
    // Follows the passes of several targets, each named as track() names
    // one, taken by priority (the first highest) where they overlap: the
    // station's schedule, seen in schedule(). Refused, naming it, when a
    // name finds no target or several; a single track() ends it.
    virtual Outcome runSchedule(const QStringList &targets, const ScheduleRequest &request) = 0;
    // Ends the schedule (and the pass of it followed), and only that;
    // refused when none runs.
    virtual Outcome stopSchedule() = 0;
    // What runSchedule would plan now for these targets, each named as
    // track() names one, moving nothing: Awaiting (planning takes a while,
    // here too) and answered by schedulePreviewed, then `answered` done;
    // or `answered` refused (no place yet; a newer preview was asked).
    // A name that finds nothing is said in the preview, not refused.
    virtual Outcome previewSchedule(const QStringList &targets, const ScheduleRequest &request) = 0;
    // The operator has looked at what the motion guard stopped: the axes
    // may be driven again. Refused when none is held.
    virtual Outcome clearMotionFaults() = 0;
    // The operator takes the radio's dial from the Doppler steering
    // (held), or hands it back; seen in the state's radioHeld.
    virtual Outcome holdRadio(bool held) = 0;
    // Turns at these speeds (°/s, signed: + clockwise and up) until
    // endJog(). Said again, each axis takes its new speed (0 stops an axis
    // the jog turned). A jog from afar is a lease the face renews while it
    // lasts. `cause` (the arrow let go of) goes to the station's log.
    virtual Outcome startJog(double azSpeed, double elSpeed) = 0;
    virtual void endJog(const QString &cause) = 0;

signals:
    void stateChanged(const slew::face::StationState &state);
    void planChanged(const slew::face::StationPlan &plan);
    void scheduleChanged(const slew::face::StationSchedule &schedule);
    void telemetryReceived(const slew::face::TelemetrySample &sample);
    void liveChanged(bool live);
    // What a prediction is made from has changed (the station's place, its
    // element sets, its clock set or started): a preview is out of date.
    void skyChanged();
    // The answer to previewSchedule, by its id, before `answered`.
    void schedulePreviewed(const QString &id, const slew::face::SchedulePreview &preview);
    // The station's answer to an intent that was Awaiting, by its id; or
    // no answer in time (refused, saying so).
    void answered(const QString &id, const slew::face::Outcome &outcome);
};

} // namespace slew::face
