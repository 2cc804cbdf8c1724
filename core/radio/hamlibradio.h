// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `hamlib:MODEL?device=...` and `sim:`: a radio driven by libhamlib in this
// process (the URIs: hamliburi.h), so no rigctld needs to run. `sim:` is
// Hamlib's dummy rig, the radio that works out of the box.
//
// Hamlib blocks, so its calls run on a worker thread (hamlibworker.h); this
// object, on the main thread, paces the commands (commandpacer.h) and
// posts one at a time, and never waits for the worker, neither in close()
// nor in its destructor: a radio stuck in a serial timeout never holds the
// event loop. A worker may outlive its link until Hamlib returns; it then
// frees the RIG and itself.
//
// The calls, as the Hamlib rig API (rig.h) names them, and the text
// commandSent() shows for each. With the Split layout (receive on VFO A,
// transmit on VFO B, most radios):
//
//   set_freq hz                  rig_set_freq, the receive frequency, on the current VFO
//   set_split_freq hz            rig_set_split_freq, the transmit frequency
//   set_split_vfo 1 VFOB         rig_set_split_vfo(current, on, VFO B) (0 VFOA: off)
//   set_mode USB 2400            rig_set_mode, the name read by rig_parse_mode
//   set_split_mode LSB 0         rig_set_split_mode, the transmit side's mode
//   get_freq, get_split_freq     the reads
//   get_split_vfo                at opening: whether split is on already
//   get_ts                       the tuning step: rig_get_ts, else the finest step
//                                the model lists for the current mode (rig_get_mode)
//
// With the Main/Sub layout (receive on Sub, transmit on Main: the IC-9700
// in satellite mode) each call names its VFO instead, and there is no
// split: `set_freq Sub hz`, `set_freq Main hz`, `set_mode Sub ...`,
// `set_mode Main ...`, `get_freq Sub`, `get_freq Main`, `get_ts Sub`.
//
// rig_set_vfo is never called. Only what Hamlib can take reaches it:
// frequencies finite, 1 Hz to 1 THz, sent in whole hertz; a mode that
// rig_parse_mode knows; a passband from -1 (unchanged) to 1 MHz. Anything
// else is refused through commandFailed() and nothing is sent, as are
// commands while the link is not open.
//
// Opening: rig_open (a serial model's device, rate and CI-V address set
// first), get_freq, then set_freq with the frequency just read, timed from
// the moment it leaves this link to its result, get_ts, and with the Split
// layout get_split_vfo; then Open. A set always reaches the radio, where
// Hamlib answers a get from its cache; setting the frequency the radio
// holds changes nothing on it. The dummy rig takes about 40 ms for a set.
//
// A call Hamlib refuses or fails reports commandFailed() with Hamlib's
// words and changes nothing. One that says the radio is gone closes the
// link with the reason: an I/O or protocol error, or a timeout twice in a
// row (Hamlib has retried each before giving up). A failed opening closes
// it too. Reopening is the owner's, with open(). Reads ask the transmit
// frequency when split is on (found at opening, or turned on since), and
// always with Main/Sub.

#include "commandpacer.h"
#include "hamliburi.h"
#include "hamlibworker.h"
#include "radiolink.h"

#include <QElapsedTimer>

#include <atomic>
#include <map>
#include <memory>
#include <optional>

namespace slew::radio {

class HamlibRadioLink : public RadioLink {
    Q_OBJECT
public:
    // What Slew tunes: from 1 Hz to 1 THz, as on the rigctld link.
    static constexpr double kMinHz = 1;
    static constexpr double kMaxHz = 1e12;
    // Timeouts in a row, each after Hamlib's own retries, that close the link.
    static constexpr int kTimeoutsBeforeClosing = 2;

    explicit HamlibRadioLink(HamlibRadioConfig config, QObject *parent = nullptr);
    ~HamlibRadioLink() override;

    void open() override;
    void close() override;
    State state() const override { return m_state; }
    // As given ("hamlib:3081?device=/dev/ttyUSB0"); "sim:" for the built-in radio.
    QString uri() const override { return m_config.uri; }

    void setReceiveHz(double hz) override;
    void setTransmitHz(double hz) override;
    void setSplit(bool on) override;
    void setMode(const QString &mode, int passbandHz) override;
    void setTransmitMode(const QString &mode, int passbandHz) override;
    void readFrequencies() override;

    // Both layouts are possible in process: a call names its VFO.
    QString setVfoLayout(VfoLayout layout) override;
    VfoLayout vfoLayout() const override { return m_wantedLayout; }

    double tuningStepHz() const override { return m_tuningStepHz; }
    int latencyMs() const override { return m_latencyMs; }
    void setMinimumIntervalMs(int ms) override { m_pacer.setMinimumIntervalMs(ms); }
    void dropWaiting() override { m_pacer.dropWaiting(); }

    const HamlibRadioConfig &config() const { return m_config; }
    // For tests and the traffic view: what the pacer holds.
    const CommandPacer &pacer() const { return m_pacer; }
    // Worker threads of any link, this one's or a destroyed one's, that
    // have not yet ended and been deleted.
    static int liveWorkers();

private:
    // What each exchange is, carried through the pacer as its tag.
    enum class Exchange {
        OpeningPort,
        OpeningRead,
        OpeningLatency,
        OpeningStep,
        OpeningSplit,
        SetReceive,
        SetTransmit,
        SetSplitOn,
        SetSplitOff,
        SetMode,
        SetTransmitMode,
        ReadReceive,
        ReadTransmit,
    };
    enum class Path { Receive, Transmit };

    // "set_freq 145800000"; with Main/Sub, the VFO too: "set_freq Sub 145800000".
    QString text(const char *call, Path path, const QString &arguments = {}) const;
    HamlibJob jobFor(const PacedCommand &command) const;
    bool acceptFrequency(const QString &command, double hz);
    void submit(CommandKind kind, Exchange exchange, const QString &text, double hz = 0, quint64 mode = 0,
                qint64 passbandHz = 0);
    void submitMode(CommandKind kind, Exchange exchange, Path path, const QString &mode, int passbandHz);
    void send(const PacedCommand &command);
    void onDone(const HamlibResult &result);
    void finishExchange(const PacedCommand &command, const HamlibResult &result);
    // True when the failure means the radio is gone.
    bool isLoss(int code);
    void becomeOpen();
    // The URI as messages start with it, without a colon of its own at the end.
    QString label() const;
    void setState(State state, const QString &detail);
    // Closes with the reason; the command in flight, if any, failed with it.
    void fail(const QString &reason);
    // The session ends: the worker skips what is left of it and frees the radio.
    void leaveSession();

    const HamlibRadioConfig m_config;
    CommandPacer m_pacer;
    HamlibWorker *m_worker = nullptr; // made at the first open(); ends itself after this is gone
    std::shared_ptr<std::atomic<int>> m_session;
    // The pacer carries a command's text and tag only. Its values are kept
    // here by kind: the newest given of each kind, which is the one the
    // pacer holds waiting, and so the one it hands to send().
    struct Values {
        double hz = 0;
        quint64 mode = 0; // Hamlib's rmode_t
        qint64 passbandHz = 0;
    };
    std::map<CommandKind, Values> m_newest;
    QElapsedTimer m_sentAt;
    quint64 m_lastSerial = 0; // the number of the job on the wire (HamlibJob::serial)
    State m_state = State::Closed;
    VfoLayout m_wantedLayout = VfoLayout::Split; // from the next opening on
    VfoLayout m_layout = VfoLayout::Split;       // this opening's
    std::optional<double> m_receiveRead;         // a read's first half, until its second comes
    bool m_splitOn = false;                      // as the radio last said or accepted
    int m_timeoutsInARow = 0;
    double m_tuningStepHz = 1.0;
    int m_latencyMs = 0;
};

} // namespace slew::radio
