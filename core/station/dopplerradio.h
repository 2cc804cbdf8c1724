// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The station's radio: its link (a rigctld, libhamlib in process, the
// built-in simulated radio, or the rotator controller's own UP/DN), what
// the tracked satellite sends and listens on, and the Doppler steering
// (radio/dopplersteering.h) while a pass is tracked.
//
//   - Steering begins at AOS of a satellite's pass that the station's pass
//     runner tracks, once the frequencies are set and the link is open, or
//     when the later of those comes during the pass. Before its first
//     frequency it sets the receive mode and, with an uplink, split and the
//     transmit mode.
//   - It ends with the tracker's pass: at LOS, on Stop, untrack, a lost
//     rotator link. Split stays on through the pass. When the operator
//     asks (setRestoreAfterPass), the radio is then put back as it was
//     found at the last reading before AOS: its receive frequency, and split
//     off again when Slew turned it on; otherwise it is left where the pass
//     ended, as Gpredict leaves it. (Modes are not read back, so not
//     restored.)
//   - A lost radio link is opened again after 1, 2, 5, 10 and then every
//     30 seconds for as long as the station wants its radio; the
//     controller's link, which rides on the rotator's, when the rotator's
//     link is back.
//   - The operator may stop radio control (holdControl): steering ends and
//     stays off until resumed.
//   - The radio never holds up the rotator: its link is its own, or for the
//     controller's UP/DN a place in the rotator session's queue like any
//     query; the station's Stop does not wait for it.
//
// What it does goes out as log lines (the service writes them) and as
// signals (the window's Radio panel shows them).

#include "radio/doppler.h"
#include "radio/radioplan.h"
#include "radio/dopplersteering.h"
#include "radio/radiolink.h"
#include "tracking/tracker.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>
#include <optional>

namespace slew::session {
class RotatorSession;
}
namespace slew::tracking {
class PassRunner;
class StationClock;
}

namespace slew::station {

using radio::RadioPlan;

class DopplerRadio : public QObject {
    Q_OBJECT
public:
    // "controller": the rotator controller's UP/DN, on `session`'s link.
    static constexpr const char *kControllerUri = "controller";

    // All three must outlive this.
    DopplerRadio(session::RotatorSession *session, tracking::PassRunner *runner,
                 const tracking::StationClock *clock, QObject *parent = nullptr);
    ~DopplerRadio() override;

    // The radio to use, by URI (radio/radiolinks.h, or "controller");
    // empty for none. False with *error, and the radio held before kept,
    // when the URI is refused. Takes effect at once: a link that was open
    // is closed, and the new one opened when the radio is wanted.
    bool setLink(const QString &uri, QString *error);
    QString linkUri() const { return m_link ? m_link->uri() : QString(); }
    radio::RadioLink *link() const { return m_link.get(); }
    radio::DopplerSteering *steering() const { return m_steering.get(); }

    // Open the link, and keep it open; close it and stop trying.
    void connectRadio();
    void disconnectRadio();
    bool isWanted() const { return m_wanted; }
    // Tries since the link was last open (0 while it is, or not wanted).
    int reopenAttempts() const { return m_reopenAttempt; }

    // What to tune: takes effect at once during a pass (the steering starts
    // over with it), else at the next AOS. Nothing: the radio is left alone.
    void setPlan(const std::optional<RadioPlan> &plan);
    const std::optional<RadioPlan> &plan() const { return m_plan; }

    // Which VFOs carry the two paths (radio/radiolink.h): split (VFOA/VFOB)
    // or Main/Sub. Empty when the link can, else why not; it applies to
    // links made after it too, and from the link's next opening.
    QString setVfoLayout(radio::VfoLayout layout);
    radio::VfoLayout vfoLayout() const { return m_layout; }

    // Put the radio back as it was found before AOS, after each pass.
    void setRestoreAfterPass(bool restore) { m_restoreAfterPass = restore; }
    bool restoresAfterPass() const { return m_restoreAfterPass; }

    // The operator's Stop of radio control: the steering ends at once and
    // the radio is left where it is, on its open link, for the operator's
    // hands; no pass is tuned until control is resumed, which tunes a pass
    // still up from then on.
    void holdControl(bool held);
    bool isControlHeld() const { return m_held; }

    // The operator tunes across the passband from the window (steps, the
    // wheel): radio/dopplersteering.h's retuneBy, the same offset the
    // radio's dial moves. Empty when it moved, else why not, in words.
    QString tuneBy(double hz);

    // Where Slew last tuned the radio or last read it to be, each path
    // when known (Hz): what a face shows beside the link. A new radio
    // (setLink) starts with none.
    const radio::RadioFrequencies &frequencies() const { return m_frequencies; }

    // Figures of the pass being tuned, or of the last one.
    bool isSteering() const { return m_steering && m_steering->isSteering(); }
    radio::DopplerFigures figures() const;

    // How often measured() is said at most: a chart needs no more.
    static constexpr int kMeasuredIntervalMs = 200;

signals:
    // setLink() made another radio (or none) the station's.
    void linkChanged();
    void linkStateChanged(slew::radio::RadioLink::State state, const QString &detail);
    // A lost link is opened again in `seconds`: try number `attempt` since it was last open.
    void reopenScheduled(int attempt, int seconds);
    void steeringChanged(bool steering);
    void controlHeldChanged(bool held);
    // The Doppler error on the receive path (Hz): the largest of the rounds
    // since the last one said, with its sign; and the transmit path's (NaN
    // when not tuned).
    void measured(double receiveErrorHz, double transmitErrorHz);
    // frequencies() changed: a frequency set or read back.
    void frequenciesChanged();
    void logLine(const QString &line);

private:
    void onLinkState(radio::RadioLink::State state, const QString &detail);
    void onPassState();
    void onCommandFailed(const QString &command, const QString &why);
    void begin();
    // `putBack`: the radio is put back as it was found (not when new frequencies follow at once).
    void end(const QString &why, bool putBack = true);
    void putBack();
    // Reads where the radio stands now, to put it back there after a pass.
    void readFound();
    void scheduleReopen();
    bool passIsUp() const;
    bool isControllers() const;
    QString describePlan() const;

    session::RotatorSession *m_session;
    tracking::PassRunner *m_runner;
    const tracking::StationClock *m_clock;
    std::unique_ptr<radio::RadioLink> m_link;
    std::unique_ptr<radio::DopplerSteering> m_steering;
    std::optional<RadioPlan> m_plan;
    bool m_wanted = false;
    bool m_restoreAfterPass = false;
    bool m_held = false;
    radio::VfoLayout m_layout = radio::VfoLayout::Split;
    int m_reopenAttempt = 0;
    QTimer m_reopen;
    // The radio as it was found before AOS, to put back after LOS.
    std::optional<double> m_foundReceiveHz;
    bool m_readingFound = false;
    tracking::Tracker::State m_lastPassState = tracking::Tracker::State::Idle;
    bool m_splitTurnedOn = false;
    radio::DopplerFigures m_lastFigures;
    static constexpr qint64 kRepeatedFailureMs = 60000;
    QString m_lastFailure;
    QElapsedTimer m_sinceFailure;
    int m_failuresNotSaid = 0;
    // measured(), thinned to kMeasuredIntervalMs: the largest of each path since the last.
    void onMeasured(double receiveErrorHz, double transmitErrorHz);
    // A frequency set or read: each path known replaces the one held.
    void noteFrequencies(std::optional<double> receiveHz, std::optional<double> transmitHz);
    radio::RadioFrequencies m_frequencies;
    QElapsedTimer m_sinceMeasured;
    double m_worstReceive, m_worstTransmit;
};

} // namespace slew::station
