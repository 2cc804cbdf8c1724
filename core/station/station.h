// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A ground station: everything Slew runs for one antenna site, with no
// window. The operator window is a view of a Station; the station service
// (`slew --headless`) is a Station with a log (stationservice.h). Every rule
// about how the parts work together is written here once:
//
//   - the rotor sessions: one, or one per rotor of a multi-rotor controller
//     sharing one line (the service's --rotors), or the one the window drives
//     with the controller's other rotors followed beside it (ControllerRotors);
//   - a rotctld server per rotor (listening only when a face asks) and its
//     holds: while Slew tracks, trackers on the port are held off; after the
//     operator's Stop they are held off until control is handed back; while a
//     remote tracker steers, Slew's own tracking waits;
//   - an alarm monitor per rotor, so the window's banner and the service's
//     log judge the same conditions in the same words;
//   - the element sets, the station's place and clock (with the built-in
//     simulator paced to it), the pass runner (the tracker);
//   - the radio, kept on the tracked satellite's Doppler-corrected
//     frequencies during a pass (dopplerradio.h);
//   - the schedule of several targets by priority (schedulerunner.h), on
//     the same pass runner, planned again when the element sets change;
//   - the record of every pass it tracks (passrecorder.h), in the pass
//     records a face opens (openPassRecords);
//   - stopping every rotor, and letting the stops leave the link, before exit.
//
// Its intent (connect, go to, stop, park, home, track, hand control back,
// the place, shut down) and its state (signals) are values: positions,
// targets, plans, alarms, states. A face that needs more reaches the parts
// through the accessors below, and never makes one of its own.

#include "face/outcome.h"
#include "model/rotatorprofile.h"
#include "session/sessiontypes.h"
#include "sky/site.h"

#include <QList>
#include <QObject>
#include <QString>

#include <memory>
#include <optional>
#include <vector>

namespace slew::face {
class StationFace;
}
namespace slew::session {
class ControllerRotors;
class MoveWatch;
class RotatorSession;
}
namespace slew::transport {
class SharedLine;
}
namespace slew::bridge {
class RotctldServer;
}
namespace slew::sky {
class ElementSetSources;
}
namespace slew::radio {
class TransponderSources;
}
namespace slew::records {
class PassRecordStore;
}
namespace slew::tracking {
class PassRunner;
class SimulatorPace;
class StationClock;
struct TrackTarget;
}

namespace slew::station {

class AlarmMonitor;
class LocalStationFace;
class DopplerRadio;
class ScheduleRunner;
struct ScheduleOptions;
class PassRecorder;
class RemoteOperation;
struct RemoteOptions;

struct StationOptions {
    // The rotors of a multi-rotor controller to serve, each with a session,
    // an alarm monitor and a rotctld server of its own, all on the one line
    // `sharedLineUri` names (transport/sharedline.h). Empty: one rotor.
    QList<int> rotors;
    QString sharedLineUri;
    // The window's way with a multi-rotor controller: it drives one rotor
    // and follows the others as they come (session/controllerrotors.h).
    bool followControllerRotors = false;
    // A service keeps trying after a loss; the window leaves it to the operator.
    bool autoReconnect = false;
    // Every rotor's profile before it connects (its link is not opened here).
    std::optional<model::RotatorProfile> profile;
};

class Station : public QObject {
    Q_OBJECT
public:
    // The window's station: one rotor, the controller's others followed.
    explicit Station(QObject *parent = nullptr);
    explicit Station(const StationOptions &options, QObject *parent = nullptr);
    ~Station() override;

    // False, with error(), when the rotors' shared line could not be made
    // from its URI: such a station has no rotors.
    bool isValid() const { return m_error.isEmpty(); }
    QString error() const { return m_error; }

    // --- The parts, for the faces that show them ---------------------------
    int rotorCount() const { return int(m_rotors.size()); }
    // 0 for the one rotor of an ordinary rotator, else the controller's 1..4.
    int rotorNumber(int index) const;
    session::RotatorSession *session(int index = 0) const;
    // The link connectRotators() opens for the rotor: its profile's, or its
    // address on the shared line.
    QString rotorUri(int index) const;
    bridge::RotctldServer *server(int index = 0) const;
    AlarmMonitor *alarms(int index = 0) const;
    // The other rotors of the controller the window drives; null when not followed.
    session::ControllerRotors *controllerRotors() const { return m_controllerRotors.get(); }
    // Where the first rotor's moves went: arrived, stopped short, replaced.
    session::MoveWatch *moveWatch() const { return m_moveWatch.get(); }
    sky::ElementSetSources *elementSets() const { return m_elementSets.get(); }
    // The satellites' transponders, cached beside the element sets; like
    // them, nothing is read or fetched until a face asks.
    radio::TransponderSources *transponders() const { return m_transponders.get(); }
    tracking::StationClock *clock() const { return m_clock.get(); }
    tracking::SimulatorPace *simulatorPace() const { return m_pace.get(); }
    tracking::PassRunner *passRunner() const { return m_runner.get(); }
    // The radio, tuned for Doppler while the pass runner tracks a satellite
    // (dopplerradio.h); null for a station with no rotor.
    DopplerRadio *radio() const { return m_radio.get(); }
    // Several targets by priority, pass after pass (schedulerunner.h); null
    // for a station with no rotor.
    ScheduleRunner *scheduleRunner() const { return m_schedule.get(); }
    // The pass records: always there, open once a face has opened them
    // (openPassRecords), and the recorder that writes every tracked pass
    // into them (null for a station with no rotor).
    records::PassRecordStore *passRecords() const { return m_records.get(); }
    PassRecorder *passRecorder() const { return m_recorder.get(); }
    // The station published and commanded over MQTT, once startRemote()
    // has made it (remoteoperation.h); null before.
    RemoteOperation *remote() const { return m_remote.get(); }

    // The station as every face shows it and asks of it, the operator at
    // the station's standing (localstationface.h); null for a station with
    // no rotor.
    face::StationFace *face() const;

    // --- Intent -------------------------------------------------------------
    // Opens every rotor's link (rotorUri()).
    void connectRotators();
    // Closes every rotor's link, as the operator asks: not a loss, so no
    // "link lost" alarm, and what can no longer be known is cleared.
    void disconnectRotators();
    // The operator's Stop: every rotor on the controller stops, Slew's own
    // tracking is not restarted by it, and trackers on the rotctld port are
    // held off until handControlBack(). Always sent when there is a link.
    // `cause` (the key, the button) goes to the logs with each stop.
    session::CommandResult stop(const QString &cause);
    // Trackers on the rotctld port may steer again after the operator's Stop.
    void handControlBack();
    // Between the operator's Stop and handControlBack(): remote control
    // (trackers, commands over MQTT) is held off.
    bool operatorHolds() const { return m_operatorHolds; }
    // Publishes the station under its name and obeys commands from the
    // broker, under the same rules as every other face (remoteoperation.h).
    // False, with *error, when it cannot start; said again, it does nothing.
    bool startRemote(const RemoteOptions &options, QString *error);
    // Follows every pass of `target` above `minElevationDeg` with the first
    // rotor, by the station's clock. Refused, saying why, when the place is
    // not set, the elements are too old, or a remote tracker steers the rotator.
    face::Outcome track(const tracking::TrackTarget &target, double minElevationDeg);
    // How far from its elements' epoch a satellite is tracked, by one target
    // and the schedule alike (sky/elementage.h); track() refuses a satellite
    // already past it, and a pass past it is not tracked.
    void setElementAgeLimitDays(double days);
    double elementAgeLimitDays() const;
    // Follows the passes of several targets, taken by priority (the first
    // highest) where they overlap and only where the rotator can get from
    // one to the next: the schedule (schedulerunner.h). Refused as track()
    // is. A single track() ends it, as untrack() does.
    // Refused too when an option is outside the ranges every face takes
    // (face/schedulerequest.h).
    face::Outcome runSchedule(const QList<tracking::TrackTarget> &targets, const ScheduleOptions &options);
    // Ends one target's tracking and the schedule alike; refused when
    // neither runs.
    face::Outcome untrack(const QString &why);
    // Ends the schedule, and the pass of it being followed; refused when no
    // schedule runs. One target tracked on its own is left alone: that is
    // untrack()'s, and an operator who ends a schedule has not asked for it.
    face::Outcome stopSchedule(const QString &why);
    // The operator takes the radio's dial (held) from the Doppler steering,
    // or hands it back (dopplerradio.h, holdControl). Never refused for want
    // of a radio: a hold is kept and applies to a radio set later, as the
    // radio part keeps it; refused only by a station with no rotor, which
    // has no radio part at all.
    face::Outcome holdRadio(bool held);
    // Who steers the first rotor from outside now ("remote tracker
    // 127.0.0.1:5533"), or empty.
    QString otherSteering() const;

    // Opens the pass records at `path` to record every pass tracked from
    // now on, keeping samples `keepDays` days. Empty when it records, else
    // why not, naming the file (nothing is recorded then). With
    // `readWhenTaken`, a file another Slew records into is opened to read
    // only (the window's History shows it), and the message says so.
    QString openPassRecords(const QString &path, int keepDays, bool readWhenTaken = false);

    // Where the antenna stands; nothing until set.
    std::optional<sky::Site> place() const { return m_place; }
    void setPlace(const std::optional<sky::Site> &place);
    // The place kept in the settings (Sky → Station…, --qth), if any, with
    // its horizon mask file. Empty, or why the mask kept could not be read
    // (the place is then set with a flat horizon).
    QString restoreSavedPlace();

    // Stops Slew's tracking, closes the rotctld servers, stops every rotor
    // and emits shutDown() once every stop has left its link (at once when
    // there is none). Said again, it does nothing more.
    void shutdown(const QString &why);
    bool isShuttingDown() const { return m_shuttingDown; }

signals:
    void placeChanged(const std::optional<slew::sky::Site> &place);
    void operatorHoldChanged(bool holds);
    // Slew's own tracking holds the first rotor, or no longer does.
    void trackingChanged(bool holdsRotator);
    // shutdown() sent rotor `number`'s stop (0: the one rotor); not said
    // for a rotor with no link to send it on.
    void exitStopSent(int number);
    // Every rotor's stop has left the link: the process may end.
    void shutDown();

private:
    struct Rotor {
        int number = 0;
        std::unique_ptr<session::RotatorSession> session;
        std::unique_ptr<bridge::RotctldServer> server;
        std::unique_ptr<AlarmMonitor> alarms;
    };
    void addRotor(int number, const StationOptions &options);
    void wireTracking();
    QList<session::RotatorSession *> everySession() const;
    // Why Slew does not track while `other` steers the rotator.
    static QString othersSteeringRefusal(QString other);

    QString m_error;
    std::unique_ptr<transport::SharedLine> m_line; // with several rotors: the one link they share
    std::vector<Rotor> m_rotors;
    std::unique_ptr<session::ControllerRotors> m_controllerRotors;
    std::unique_ptr<session::MoveWatch> m_moveWatch;
    std::unique_ptr<sky::ElementSetSources> m_elementSets;
    std::unique_ptr<radio::TransponderSources> m_transponders;
    std::unique_ptr<tracking::StationClock> m_clock;
    std::unique_ptr<tracking::SimulatorPace> m_pace;
    std::unique_ptr<tracking::PassRunner> m_runner;
    std::unique_ptr<DopplerRadio> m_radio; // after the runner and clock it follows
    std::unique_ptr<ScheduleRunner> m_schedule; // after the runner it drives
    std::unique_ptr<records::PassRecordStore> m_records;
    std::unique_ptr<PassRecorder> m_recorder; // after the store it writes to and the parts it follows
    std::unique_ptr<RemoteOperation> m_remote; // after every part it publishes
    std::unique_ptr<LocalStationFace> m_face;  // after every part it shows
    std::optional<sky::Site> m_place;
    bool m_shuttingDown = false;
    bool m_operatorHolds = false;
    int m_stillStopping = 0;
    void stoppedOne(); // a rotor's stop (or the remote's goodbye) has left
};

} // namespace slew::station
