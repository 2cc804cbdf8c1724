// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// RotatorSession: one conversation with one rotator controller.
//
// It owns the link (serial, TCP, simulator, rotctld — it never asks which),
// queues queries and matches their replies, polls position and telemetry,
// probes what the controller can do, and turns operator intent (go to, jog,
// stop, park, home, config) into the dialect's bytes after checking the
// profile's limits. Everything is driven by signals; nothing here waits.

#include "controllerchannel.h"
#include "controllerlogallowance.h"
#include "joglegs.h"
#include "echofilter.h"
#include "lineturnaround.h"
#include "linktimer.h"
#include "motionguard.h"
#include "model/movegate.h"
#include "model/rotatorprofile.h"
#include "pollpace.h"
#include "refusalowner.h"
#include "protocol/checksum.h"
#include "protocol/firmware.h"
#include "protocol/codec.h"
#include "requestqueue.h"
#include "transport/linkfactory.h"
#include "sessiontypes.h"
#include "unreadablereplies.h"

#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QTimer>

#include <array>
#include <functional>
#include <memory>
#include <optional>

namespace slew::transport {
class Link;
}

namespace slew::session {

class ControllerRadioCommands;
class Micro2gCalibration;

// Private ControllerChannel: the narrow face its helpers (the radio
// commands, the Micro-2g calibration) get, with no access to the rest.
class RotatorSession : public QObject, private ControllerChannel {
    Q_OBJECT
public:
    enum class State { Disconnected, Connecting, Connected, Reconnecting };
    Q_ENUM(State)
    // What an azimuth given to gotoAxis() means.
    enum class AzimuthIs { Bearing, Position };

    struct Options {
        int replyTimeoutMs = 500;
        int retries = 2;            // resends of an unanswered query
        int telemetryEvery = 10;    // telemetry once per this many position polls
        bool autoReconnect = false; // retry a lost link with backoff
        int maxQueue = 64;
        // With polling paused, a dialect that has a keep-alive (GS-232's `?`)
        // is sent one this often, so a dead link is noticed while idle.
        int keepAliveMs = 3000;
    };

    explicit RotatorSession(QObject *parent = nullptr);
    ~RotatorSession() override;

    void setProfile(const model::RotatorProfile &profile);
    const model::RotatorProfile &profile() const { return m_profile; }
    // The controller's language as the profile names it: what it can do,
    // and how its commands are written (protocol/codec.h).
    const protocol::Codec &codec() const override { return *m_codec; }
    // The controller's firmware (the profile's, or the SatNOGS dialect's
    // own) and what it does that its dialect does not say.
    protocol::Firmware firmware() const { return protocol::firmwareOf(m_profile.dialect, m_profile.firmware); }
    const protocol::FirmwareTraits &firmwareTraits() const { return protocol::firmwareTraits(firmware()); }
    // How close the controller stops each axis by design: the profile's
    // figure where it has one, else the firmware's.
    double azStopToleranceDeg() const { return m_profile.stopToleranceAzDeg.value_or(firmwareTraits().azToleranceDeg); }
    double elStopToleranceDeg() const { return m_profile.stopToleranceElDeg.value_or(firmwareTraits().elToleranceDeg); }
    void setOptions(const Options &options);
    const Options &options() const { return m_options; }

    // Where the session gets its link from a URI: createLink() unless set.
    // A controller with several rotors on one line gives each rotor's
    // session a link from one SharedLine (transport/sharedline.h).
    using LinkMaker = std::function<transport::LinkResult(const QString &uri)>;
    void setLinkMaker(LinkMaker maker) { m_linkMaker = std::move(maker); }

    State state() const { return m_state; }
    bool isConnected() const { return m_state == State::Connected; }
    QString uri() const { return m_uri; }
    // The open link, for tests and diagnostics (e.g. the simulator behind a
    // sim: link); null when there is none. The session keeps ownership.
    transport::Link *link() const { return m_link.get(); }
    const Capabilities &capabilities() const { return m_caps; }
    // Limits the link reported (rotctld's \dump_state), if any; moves must
    // fit these as well as the profile's.
    std::optional<model::RotatorLimits> reportedLimits() const { return m_gate.reportedLimits(); }
    // The gate every move passes (model/movegate.h), and what it would say
    // now to a go-to: for widgets that show a target before it is sent.
    // It works in the pointing frame (below): its limits are the travel
    // shifted by the calibration offsets.
    const model::MoveGate &moveGate() const { return m_gate; }
    model::MoveCheck previewPointing(double az, double el) const;
    // What the gate says to a value for park register 7 (azimuth) or 8
    // (elevation), which holds the controller's own, uncalibrated angle.
    model::MoveCheck previewParkRegister(int reg, double value) const;

    // The pointing frame. The antenna points at the controller's reading
    // plus the profile's calibration offsets (azOffsetDeg, elOffsetDeg), and
    // every position this session takes or gives is in that frame: readings,
    // targets, go-tos, the gate's limits. Only what is the controller's own
    // stays uncorrected: the bytes on the wire, raw lines, the registers and
    // the park position they hold. An azimuth-only controller has no
    // elevation offset.
    double azimuthOffset() const { return m_profile.azOffsetDeg; }
    double elevationOffset() const { return isAzimuthOnly() ? 0.0 : m_profile.elOffsetDeg; }
    // Where PARK takes the antenna. A controller with park registers (CW7/CW8,
    // hasParkRegisters()) parks where they say, whatever the profile thinks:
    // they are read on every connect, after the probe, and until both are in
    // parkKnown() is false and these fall back to the profile's guess. The
    // probe reads them, so that no client that waits for it (slewctl's
    // park) sends PARK before they are in. A
    // controller without them parks at the profile's position (by a go-to, or
    // its own command), which is then as known as it gets.
    // (rotatorsession_registers.cpp)
    bool hasParkRegisters() const;
    bool parkKnown() const;
    // The controller's own angles (uncalibrated), as the registers hold them.
    double controllerParkAzimuth() const;
    double controllerParkElevation() const;
    // The same in the pointing frame.
    double parkAzimuth() const { return controllerParkAzimuth() + azimuthOffset(); }
    double parkElevation() const { return controllerParkElevation() + elevationOffset(); }

    bool hasPosition() const { return !std::isnan(m_az) && !std::isnan(m_el); }
    // A position has come on the link open now. Until then the last link's
    // (hasPosition) is shown, stale, and no move is sent (requirePositionRead).
    bool positionReadOnThisLink() const { return m_positionReadOnLink; }
    // Moves wait for that first position: true while the controller could
    // report one and has not yet on this link (never for Easycomm I).
    bool awaitingPosition() const;
    // Why moves wait, in the words a refusal uses; empty when they do not.
    QString positionNotRead() const;
    // Lines written but held for the line's turn-around (a half-duplex
    // RS485 controller), not yet on the link: heldLinesWritten() when gone.
    bool linesHeld() const { return m_turnaround.holding(); }
    double azimuth() const { return m_az; }
    double elevation() const { return m_el; }
    bool positionStale() const { return m_stale; }
    // The last target shown to the operator; stays after a stop, for display.
    double targetAzimuth() const { return m_targetAz; }
    double targetElevation() const { return m_targetEl; }
    // Where the rotator was told to go and, as far as the session knows, is
    // still going. Empty once anything else has been sent to it: a stop, a
    // jog, park, home, a raw line, an alarm from the controller, or a link
    // that closed or (re)opened. A tracker's deadband compares against this,
    // so a target repeated after any of those goes out again.
    std::optional<PointingTarget> activeTarget() const { return m_activeTarget; }
    StatusWord status() const { return m_status; }
    int errorFlags() const { return m_errorFlags; }
    const Telemetry &telemetry() const { return m_telemetry; }
    QString version() const { return m_version; }
    int queuedRequests() const { return m_queue.size(); }
    int echoesIgnored() const { return m_echoes.ignored(); }
    // The link's lines carry the XOR checksum (`checksum=1`, link.h), and
    // how many received lines were refused for a wrong or missing one.
    bool checksumming() const { return m_checksum; }
    // The rotor of a multi-rotor controller this session drives (`rotor=n`
    // on the link's URI; 0: the controller's default rotor).
    int rotor() const { return m_rotor; }
    // The controller turns azimuth only (the Micro-2g): elevation reads 0,
    // and the gate allows no elevation but 0.
    bool isAzimuthOnly() const { return m_codec->isAzimuthOnly(); }
    int checksumFailures() const { return m_checksumFailures; }
    // Refused frames in a row after which badFramesAlarm(true) is raised.
    static constexpr int kBadFramesAlarm = 3;

    // After a stop, the zero-speed hold that brakes a free-running drive is
    // still to be sent (stopHoldSent() follows, or nothing if a move comes first).
    bool stopHoldPending() const { return m_stopHoldTimer.isActive(); }

    bool isPolling() const { return m_pollingEnabled; }
    // How often position is polled while anything happens, and how long a
    // reply may take: the profile's rate and the options' timeout, slowed
    // to what the line carries where the link knows its baud rate
    // (LinkHints::baud).
    int pollIntervalMs() const { return m_pace.fullMs(); }
    // How often once the rotator rests and nobody asks (PollPace): the
    // profile's restPollHz, never faster than the full rate.
    int restPollIntervalMs() const { return m_pace.restMs(); }
    // Polling at the slow rate now. Any command, a client's request
    // (wakePolling), an alarm or motion seen in a reply ends it at once.
    bool pollingAtRest() const { return m_pollingAtRest; }
    // The finest step a set-position expresses: a SPID controller's pulse
    // (from its replies: half a degree at 2 pulses a degree; a Rot1Prog's
    // whole degree), or the dialect's decimals (GS-232: 1°, Easycomm III:
    // 0.01°). A target between two steps goes out rounded to one of them.
    double setResolutionDeg() const;
    int replyTimeoutMs() const { return m_replyTimeoutMs; }
    // Text lines a SPID controller wrote among its binary replies (MD-01
    // firmware logs so); skipped, and reported once a connection.
    int textLinesSkipped() const { return m_textLinesSkipped; }
    // Replies this connection that no parser could read (garbage, SPID
    // frames with digits out of range, bytes outside a frame). Each is
    // logged through a small allowance (controllerlogallowance.h), and a
    // stream of them is a condition: unreadableRepliesAlarm().
    qint64 unreadableReplies() const { return m_unreadableReplies; }
    // Requests the controller refused with its "no" (`?`, `?>`) on this
    // link: a controller that says so aloud (K3NG's) rather than stay
    // silent, which the dialect identifier tells apart by.
    int refusedRequests() const { return m_refusedRequests; }
    bool unreadableRepliesAlarmed() const { return m_unreadable.raised(); }
    void setPolling(bool enabled);

    // The Micro-2g program's calibration listings, asked for on this link
    // (micro2gcalibration.h).
    Micro2gCalibration *micro2g() const { return m_micro2g.get(); }
    // The Easycomm station commands for the radios (UP, DN, UM, DM) on this
    // link (controllerradiocommands.h).
    ControllerRadioCommands *radioCommands() const { return m_radioCommands.get(); }

public slots:
    // Someone wants the rotator watched closely (a tracker steers, even
    // when its target is held back by the deadband and nothing is sent):
    // polling at the full rate again, from now. Commands, alarms and motion
    // wake it by themselves; reading the position does not.
    void wakePolling();
    // What the log allowance has held back about the controller's replies,
    // said now as one summary line (if anything was): for a service about
    // to exit, which would otherwise lose the count. The session says it
    // by itself when the link closes, and ControllerLogAllowance::kSummaryMs
    // after a line was first held back.
    void reportHeldBack();
    void connectTo(const QString &uri);
    void disconnectFromRotator();

    // Each is refused (the result says why, and commandRefused() too) when
    // the move does not pass the gate, the controller lacks the command, or
    // there is no link; then nothing is sent.
    CommandResult gotoPosition(double az, double el); // az a bearing: the gate picks the position
    // One axis only, the other left where it is going (Easycomm I and GS-232
    // can only command both: there the other axis gets its current position).
    // A Bearing azimuth is chosen as gotoPosition does; an azimuth Position is
    // exactly that mechanical angle (a tuning step).
    CommandResult gotoAxis(slew::session::Axis axis, double degrees, AzimuthIs meaning = AzimuthIs::Bearing);
    CommandResult moveAxis(slew::session::Axis axis, double degreesPerSecond); // + is right (CW) / up
    // A move by offsets from the present (polled) position, as GS-232's
    // `O+aaa-eee`: the target is worked out here, passes the gate as the
    // mechanical positions it names, and goes out as an absolute set
    // position in every dialect (docs/protocol.md says why not `O`).
    CommandResult moveBy(double azimuthOffset, double elevationOffset);
    // Exactly these positions on the rotator's own scale (in the pointing
    // frame): an azimuth past 360° (the overlap) or below 0° (a south stop),
    // an elevation past 90° (the flip), as a planned path names them
    // (tracking/passplanner.h). Gated as positions.
    CommandResult gotoUnwrapped(double azimuth, double elevation);
    // `cause` says who or what asked, for the logs: "the Esc key", "a rotctld
    // client (127.0.0.1:40522)", "the MQTT jog's lease ran out".
    CommandResult stop(const QString &cause, slew::session::Axes axes = slew::session::Axes::Both);
    CommandResult park();
    CommandResult home();
    // The motion guard (motionguard.h): an axis Slew drives that does not
    // move, or runs the wrong way, is stopped and held: every move that
    // would drive it is refused, saying why, until the operator clears it.
    void setMotionGuard(const MotionGuardSettings &settings);
    const MotionGuardSettings &motionGuard() const { return m_guards[0].settings(); }
    // Why the axis is held, in words ("Azimuth did not move for 5.0 s …"); empty when not.
    QString motionFault(slew::session::Axis axis) const { return m_motionFaults[axis == Axis::Azimuth ? 0 : 1]; }
    bool hasMotionFault() const { return !m_motionFaults[0].isEmpty() || !m_motionFaults[1].isEmpty(); }
    // The operator has looked: the axes may be driven again. `who` goes to
    // the logs ("the window", "a command over MQTT"). False when none was held.
    bool clearMotionFaults(const QString &who);
    CommandResult readConfig(int reg);
    CommandResult writeConfig(int reg, const QString &value);
    CommandResult sendRaw(const QString &line);

signals:
    void stateChanged(slew::session::RotatorSession::State state, const QString &detail);
    void profileChanged(); // limits, park, dialect or poll rate changed
    void positionChanged(double az, double el, bool stale);
    void targetChanged(double az, double el);
    // The rotator is heading for no known target any more: a stop went out,
    // or a park to a position not read yet.
    void targetCleared();
    void commandedChanged(double az, double el); // CR10 / CR11 read back
    void statusChanged(slew::session::StatusWord status);
    void errorFlagsChanged(int flags);
    void telemetryChanged(const slew::session::Telemetry &telemetry);
    void encodersChanged(double az, double el, double azVelocity, double elVelocity);
    void configValueReceived(int reg, const QString &value);
    // parkKnown() or the park position changed: the registers came in, or
    // were forgotten with the link.
    void parkChanged();
    void versionChanged(const QString &version);
    void capabilitiesChanged(const slew::session::Capabilities &capabilities);
    void stopHoldSent();
    void heldLinesWritten();
    // A stop went to the wire, whoever asked (the window, a rotctld client,
    // shutdown): whatever was driving the rotator ends here. `cause` is the
    // one stop() was given.
    void stopSent(const QString &cause);
    void bytesSent(const QByteArray &bytes);
    void bytesReceived(const QByteArray &bytes);
    void alarmReceived(const QString &text);
    void commandRefused(const QString &reason);
    // A move refused because it would leave the limits or drive an axis
    // further into the stop it rests on (also reported by commandRefused).
    void moveRefused(const QString &reason);
    // A move, stop hold aside, went to the wire.
    void moveSent();
    // The controller answered a command that went out with its "no" (`?`,
    // `?>`): nothing of it happens, and whoever waits for the move stops
    // waiting. Also reported by moveRefused() for the operator.
    void controllerRefusedMove(const QString &reason);
    void requestFailed(const QString &request, const QString &reason);
    // The motion guard stopped an axis (text: what was seen, as motionFault
    // says it), or the operator cleared every fault (text empty, `who`).
    void motionFaultChanged(slew::session::Axis axis, const QString &text);
    void motionFaultsCleared(const QString &who);
    // kBadFramesAlarm received lines in a row failed their checksum (on),
    // or a good one has arrived since (off). Nothing from a refused line is
    // acted on; the alarm says the link itself is damaging what it carries.
    void badFramesAlarm(bool on, const QString &text);
    // The controller's replies are unreadable as a stream, not now and then
    // (unreadablereplies.h): raised once with how many came in how long;
    // off when readable replies have come back for a while, or the link
    // closes. Readable replies among the garbage are still used meanwhile.
    void unreadableRepliesAlarm(bool on, const QString &text);
    // Something went wrong. Lines about what the controller sent are
    // escaped, cut and rate-limited here, with a summary of what was held
    // back, so every receiver may log each one as it comes.
    void errorOccurred(const QString &message);

private:
    // The channel its helpers ask through (controllerchannel.h). A request
    // of a helper's own is refused, as the session's own are, with no link
    // or a full queue.
    CommandResult queueRequest(Request request, SameLine same) override;
    CommandResult requireLink() override;
    void writeCommand(const QByteArray &line) override { write(line); }
    int retries() const override { return m_options.retries; }
    void reportRequestFailed(const QString &line, const QString &reason) override { emit requestFailed(line, reason); }
    // Refuses a move (refuseMove, unless Quietly) while the controller's
    // position, which it could report, has not been read on this link.
    enum class Report { Refusing, Quietly };
    CommandResult requirePositionRead(Report report = Report::Refusing);
    static bool isRawMove(const protocol::Message &m);
    void setListingReader(std::function<bool(const protocol::Message &)> reader) override
    {
        m_listingReader = std::move(reader);
    }
    void forgetActiveTarget() override { m_activeTarget.reset(); }

    void setState(State s, const QString &detail = {});
    void openLink();
    void onLinkOpened();
    void onLinkDown(const QString &reason); // failed to open, or lost
    void dropLink(const QString &reason = {});
    void scheduleReconnect(const QString &reason);
    void onReadyRead();
    void onFrame(protocol::FrameCheck check, QByteArrayView line);
    void clearBadFrames();
    // A line about what the controller sent, through the allowance.
    void reportFromController(ControllerLogAllowance::Kind kind, const QString &line);
    void noteUnreadable(const QString &reason);
    void clearUnreadable();
    void apply(const protocol::Message &m);
    void applyPosition();
    void applyInput(int index, double value);
    void applyConfig(int reg, const QString &text, bool numeric, double value);

    CommandResult refuse(const QString &reason) override;
    CommandResult refuseMove(const QString &reason); // refuse(), and moveRefused()
    // The gate's answer to one message of a raw line, empty when it may go.
    QString rawMoveRefusal(const protocol::Message &m) const;
    std::optional<double> knownAzimuth() const;
    // The gate's limits: the profile's (or the link's) travel moved into the
    // pointing frame.
    void updateGateLimits();
    // An elevation the profile's travel allows but the offset moves just out
    // of reach (90° with a -1° offset on a 0..90° rotator) is taken to the
    // nearest reachable one; any other is left for the gate to judge.
    double withinOffsetReach(double elevation) const;
    enum class LineKind { Command, Request }; // a request waits for its answer
    void write(const QByteArray &line, LineKind kind = LineKind::Command);
    void writeNow(const QByteArray &bytes); // framed, past the line's turn-around
    void writeMove(const QByteArray &line); // a new move: the pending stop hold is void
    void sendStopHold();
    void rememberSent(const protocol::Message &m) { m_echoes.noteSent(m, nowMs()); }
    bool enqueue(Request r);
    void sendNext();
    void onReplyTimeout();
    void finishFront(bool ok, const QString &reason);

    void startProbe();
    void probeAnswered(); // one probe request has ended; the last ends the probe
    void readParkRegistersInProbe();
    void forgetParkRegisters();
    void noteParkRegister(int reg, double value); // a CR7/CR8 reply, whoever asked
    void poll();
    int telemetryEveryPolls() const; // one poll in this many also asks for telemetry
    // The poll timer (and the stale timer that follows it) at the interval
    // the pace says now; a change starts the period afresh.
    void retimePolling();
    int staleAfterMs(int pollMs) const;
    void keepAlive();
    void checkSoftLimits();
    void onStale();

    model::RotatorProfile m_profile;
    Options m_options;
    // The controller's language: what to send, and what its replies say.
    // Made anew when the profile names another dialect.
    std::unique_ptr<protocol::Codec> m_codec;
    bool m_checksum = false;
    int m_rotor = 0; // from the link's hints when it opens
    protocol::ChecksumReader m_frames; // checksummed lines are checked here before the parser
    int m_checksumFailures = 0;
    int m_badFramesInARow = 0;

    QString m_uri;
    LinkMaker m_linkMaker;
    std::unique_ptr<transport::Link> m_link;
    State m_state = State::Disconnected;
    bool m_wantConnected = false;
    int m_reconnectAttempt = 0;
    QTimer m_reconnectTimer;

    RequestQueue m_queue;
    bool m_onWire = false;
    LinkTimer m_replyTimer;
    LineTurnaround m_turnaround; // the pause a half-duplex line needs after each reply

    LinkTimer m_pollTimer;
    PollPace m_pace;
    bool m_pollingAtRest = false;
    bool m_pollingEnabled = true;
    int m_pollCount = 0;
    int m_failedPolls = 0;
    // Asking again for a position the probe could not read.
    struct PositionRetry {
        static constexpr int kFirstMs = 2000;
        static constexpr int kLongestMs = 64000;
        qint64 dueMs = 0;
        int delayMs = kFirstMs;
    } m_positionRetry;
    LinkTimer m_staleTimer;
    LinkTimer m_keepAliveTimer;

    model::MoveGate m_gate; // the profile's limits and the link's, if it reports them
    std::optional<model::RotatorLimits> m_linkLimits; // as reported, uncorrected
    Capabilities m_caps;
    int m_probesOutstanding = 0;
    std::array<std::optional<double>, 2> m_parkRegister; // CW7, CW8 as read on this link
    QHash<QByteArray, int> m_telemetryFailures; // consecutive misses per telemetry query

    double m_az = kUnknown, m_el = kUnknown;
    bool m_azFresh = false, m_elFresh = false;
    bool m_stale = true;
    bool m_positionReadOnLink = false; // a position has come on the link open now
    double m_targetAz = kUnknown, m_targetEl = kUnknown;
    std::optional<PointingTarget> m_activeTarget;
    double m_commandedAz = kUnknown, m_commandedEl = kUnknown;
    std::array<double, 2> m_jogSpeed{0.0, 0.0}; // °/s of a running velocity move, per axis
    LinkTimer m_stopHoldTimer;
    bool m_holdAzimuth = false, m_holdElevation = false;
    StatusWord m_status;
    int m_errorFlags = -1;
    Telemetry m_telemetry;
    QString m_version;

    EchoFilter m_echoes; // recently sent set-commands, to recognise a controller that echoes them
    RefusalOwner m_refusals; // which line a controller's `?` answers
    void applyRefusal(const protocol::Message &m);
    QElapsedTimer m_clock; // the wall clock, for links that keep no stepped clock
    // Writes a set-position the gate has already passed, and makes it the
    // active target; go-to and relative moves share it. Pointing frame in,
    // the controller's angles out.
    CommandResult sendSetPosition(double az, double el);
    // A jog on a controller with set-position but no command to run an
    // axis (joglegs.h): a go-to towards the end of the travel that way,
    // which the release's stop ends, as a speed jog's would.
    CommandResult jogBySetPosition(Axis axis, double degreesPerSecond);
    JogLegs::Where jogWhere() const;
    JogLegs m_jogLegs;
    std::array<AxisMotionGuard, 2> m_guards;  // azimuth, elevation
    std::array<QString, 2> m_motionFaults;    // why each axis is held
    // The guards told a move began (both axes to a target), a jog's
    // direction, or a stop; each reading checked; a fault stops and holds.
    void guardMove(std::optional<double> az, std::optional<double> el);
    void guardJog();
    void guardControllersOwnMove();
    void guardAxis(Axis axis, double target);
    double arrivedWithinDeg(size_t axis) const;
    void checkMotion();
    // Why a move that takes the axes to these positions (none: the axis is
    // not driven) may not go, or empty.
    QString motionHold(std::optional<double> az, std::optional<double> el) const;
    QString axisHeld(Axis axis) const; // why a move that drives the axis may not go, or empty
    void updatePollPace();
    qint64 nowMs() const;  // the link's time where it is stepped, else m_clock's
    int m_replyTimeoutMs = 500;
    int m_textLinesSkipped = 0;
    ControllerLogAllowance m_controllerLog;
    LinkTimer m_heldBackReport; // a summary does not wait for the next allowed line for ever
    UnreadableReplies m_unreadable;
    std::function<bool(const protocol::Message &)> m_listingReader;
    std::unique_ptr<Micro2gCalibration> m_micro2g;
    std::unique_ptr<ControllerRadioCommands> m_radioCommands;
    qint64 m_unreadableReplies = 0;
    int m_refusedRequests = 0;
};

} // namespace slew::session
