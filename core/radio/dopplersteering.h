// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Keeps a radio on a satellite's Doppler-corrected frequencies while a pass
// is tracked, through a RadioLink:
//
//   - The command leads by the radio's latency (measured by the link, or
//     set): the frequency sent is the one due when the radio has taken it,
//     and further by half the time it will be held, so the error swings
//     from -step/2 to +step/2 around the truth instead of 0 to step.
//   - Commands are a budget (maxCommandsPerSecond, F and I together, in
//     any sliding second): the step each frequency may drift before it is
//     sent again is the larger of the threshold, the radio's tuning step,
//     and what its Doppler rate over its share of the budget allows; the
//     shares go by rate^(2/3), which makes the sum of the two squared
//     errors least. The link keeps only the newest value waiting, so a slow
//     bus skips stale values instead of queueing them.
//   - The dial: the receive frequency is read back. A new receive
//     frequency goes out only in answer to a reading that has just shown the
//     last one taken (so it cannot land unseen on a turn made since): a
//     reading that is none of Slew's recent frequencies is the operator's
//     hand. Slew then sends nothing until the dial has rested (dialRestMs),
//     takes the new point as the operator's, moves the uplink with it (the
//     opposite way on an inverting transponder), and goes on correcting
//     from there. It never sends the old frequency back over a turn.
//   - The window's tuning (retuneBy): the same offset the dial moves, moved
//     by steps instead, kept within the transponder's passband when it is
//     known; the radio follows it at the next reading.

//
// step() does one round at a given time, so tests and benchmarks run it on
// simulated time; start() runs it from a timer on the station clock.
//
// Each round also measures how far the radio is from the truth: the
// frequency it holds (the last one sent, from when the radio has taken it:
// a lead after it was sent) against the Doppler-corrected frequency due at
// that moment, on each path Slew tunes. figures() sums them over the pass
// (from begin()); rounds while the operator's hand is on the dial, and
// before the radio has taken a first command, are not counted. The truth a
// frequency is measured against is the one for the dial offset it was sent
// for: the operator's retune is where the operator wants the radio, not an
// error of the Doppler correction, and until the radio has taken the first
// frequency of the new point it still holds one that was right for the old.
// The offset itself is a figure of its own (DopplerFigures::dialOffsetHz).

#include "doppler.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <deque>
#include <functional>
#include <optional>

namespace slew::tracking {
class StationClock;
}

namespace slew::radio {

class RadioLink;
struct RadioFrequencies;

// How far the radio was from the truth over a pass, receive and transmit
// paths together, in hertz.
struct DopplerFigures {
    double rmsHz = 0;
    double worstHz = 0; // the largest error, unsigned
    int samples = 0;    // one a round and path
    int commands = 0;   // frequencies sent
    // Where the operator's dial has moved the downlink from the plan's
    // (at the satellite; the uplink follows as the plan says): no error.
    double dialOffsetHz = 0;
};

// "error RMS 1.5 Hz, worst 16.9 Hz over 57647 readings; 5188 frequencies
// sent", and "; dial offset +14 000 Hz" when the operator's dial moved the
// downlink: the figures as the log and the Radio tab say them.
QString describeFigures(const DopplerFigures &figures);

class DopplerSteering : public QObject {
    Q_OBJECT
public:
    struct Settings {
        double thresholdHz = 2.0;     // the least drift worth a command
        int maxCommandsPerSecond = 19; // F and I together, in any sliding second
        int leadMs = -1;              // -1: the link's measured latency
        int stepMs = 20;              // how often start()'s timer runs step()
        int readBackMs = 40;          // how often the dial is read, when it is followed
        int dialRestMs = 400;         // a dial that has rested this long is the operator's new point
        bool followDial = true;
    };
    // The range-rate (km/s) at a Julian date; nothing when it is unknown.
    using RangeRate = std::function<std::optional<double>(double julian)>;

    explicit DopplerSteering(RadioLink *link, QObject *parent = nullptr);

    void setSettings(const Settings &settings) { m_settings = settings; }
    const Settings &settings() const { return m_settings; }

    // Steers from now on; a second call replaces the satellite.
    void begin(const SatelliteFrequencies &satellite, RangeRate rangeRate);
    void end();
    bool isSteering() const { return bool(m_rangeRate); }
    // The satellite's frequencies as they now stand: the operator's dial
    // turns are in them (the plan's, moved by dialOffsetHz()).
    SatelliteFrequencies satellite() const { return retuned(m_dialOffsetHz); }
    // How far the operator's dial has moved the downlink since begin(), at
    // the satellite.
    double dialOffsetHz() const { return m_dialOffsetHz; }
    // The operator tunes from the window: the downlink moves by `hz` (at
    // the satellite) and the uplink with it, as a turn of the dial moves
    // them, up to the passband's edge. How far it moved; 0 with *why when
    // it cannot: no pass steered, the hand on the dial, or at the edge.
    double retuneBy(double hz, QString *why);

    // One round at `julian` (the station clock) and `nowMs` (a monotonic
    // clock of the same pace).
    void step(double julian, qint64 nowMs);
    // step() from a timer on `clock` (which must outlive this).
    void start(const tracking::StationClock *clock);
    void stop();

    // What Slew last told the radio, quantised as sent.
    std::optional<double> sentReceiveHz() const { return m_sentReceive; }
    std::optional<double> sentTransmitHz() const { return m_sentTransmit; }
    bool dialTurning() const { return m_dial.has_value(); }
    int commandsSent() const { return m_commandsSent; }
    // The pass so far (since begin()).
    DopplerFigures figures() const;

signals:
    void tuned(const slew::radio::RadioTuning &tuning);
    // The operator's dial moved the downlink by this much (Hz, at the satellite).
    void dialFollowed(double offsetHz);
    // A round's error on the receive path (the radio's frequency less the
    // truth, Hz), and the transmit path's when Slew tunes it (else NaN).
    void measured(double receiveErrorHz, double transmitErrorHz);

private:
    void onRead(const RadioFrequencies &frequencies);
    void judgeReading(const RadioFrequencies &frequencies);
    // The dial has rested: its point is the operator's. `overwritten`: a
    // command of Slew's landed over the turn, and the point is sent back.
    void adoptDial(bool overwritten);
    // Sends what has drifted past its step, as the budget allows.
    void sendDue();
    bool withinBudget();
    void noteSent();
    bool isOwn(double receiveHz) const;
    // The plan's frequencies with the downlink moved by `dialOffsetHz`, and
    // the uplink with it as the plan says it follows.
    SatelliteFrequencies retuned(double dialOffsetHz) const;
    // A frequency on the radio from `fromMs` on, sent for the dial offset
    // then (what its error is measured against).
    struct Held {
        double hz;
        qint64 fromMs;
        double dialOffsetHz;
    };
    void noteHeld(std::deque<Held> &held, double hz, qint64 fromMs) const;
    // What the radio holds at `nowMs`, as far as known.
    static std::optional<Held> heldAt(const std::deque<Held> &held, qint64 nowMs);
    void measure();
    bool followsDial() const;
    int leadMs() const;
    double tuningStepHz() const;

    RadioLink *m_link;
    Settings m_settings;
    SatelliteFrequencies m_satellite; // as planned, without the operator's dial
    double m_dialOffsetHz = 0;
    RangeRate m_rangeRate;
    std::optional<double> m_sentReceive, m_sentTransmit;
    struct Sent {
        double hz;
        qint64 atMs;
    };
    std::deque<Sent> m_recentReceive; // to tell Slew's own commands from the dial
    struct Dial {
        double hz;          // where the dial was last read
        qint64 sinceMs;     // since when it has read that
    };
    std::optional<Dial> m_dial;
    bool m_receiveTaken = true; // a reading has shown the last receive frequency on the radio
    bool m_readPending = false;
    bool m_answeringRead = false; // in onRead(): a reading has just come
    int m_receivesSent = 0;       // receive frequencies sent since begin()
    int m_receivesBeforeRead = 0; // ...when the pending read was asked
    std::deque<qint64> m_sendTimes; // the last second's commands, for the budget
    double m_lastJulian = 0;
    qint64 m_nowMs = 0;
    qint64 m_lastReadMs = -1;
    int m_commandsSent = 0;
    std::deque<Held> m_heldReceive, m_heldTransmit; // sent, and from when each is on the radio
    double m_sumSquares = 0;
    double m_worst = 0;
    int m_samples = 0;
    int m_commandsAtBegin = 0;
    const tracking::StationClock *m_clock = nullptr;
    QTimer m_timer;
    QElapsedTimer m_monotonic; // start()'s nowMs: one clock for the steering's whole life
};

} // namespace slew::radio
