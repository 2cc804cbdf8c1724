// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `rigctld://host:port`: a radio behind a running rigctld (Hamlib's radio
// daemon, port 4532 by default), so Slew tunes any radio Hamlib drives.
//
// Every command is sent in the extended response form (`+F 145800000`),
// whose answer echoes the command and ends with `RPRT n`; the default form
// is understood too (rigctldreply.h). The commands, as the rigctld manual
// names them:
//
//   +F hz         set_freq        the receive frequency, on the current VFO
//   +I hz         set_split_freq  the transmit frequency, on the split VFO
//   +S 1 VFOB     set_split_vfo   split on, transmitting on VFOB (+S 0 VFOA: off)
//   +M mode pb    set_mode
//   +X mode pb    set_split_mode  the transmit side's mode
//   +f, +i        get_freq, get_split_freq
//   +s            get_split_vfo   at opening: whether split is on
//   +n            get_ts          the tuning step
//
// Only what rigctld can take goes out. Frequencies in whole hertz, finite
// and in range: rigctld 4.5.4 with its dummy rig answers `F nan` with
// RPRT 0 and then reads a frequency of -9223372036854775808. A mode as one
// token of letters and digits: rigctld reads what follows a command on its
// line as further commands (`+F 145800000 extra` answers six more
// lines). set_vfo (`V`) is never sent: without its argument rigctld
// takes the next line as the VFO, and a command it does not know
// (`\nonsense`) gets no answer at all, which the reply timeout catches.
//
// VFO mode (rigctld -o, --vfo): every command then names its VFO, and a
// command without one is misread (`+F 145800000` takes the number for a
// VFO). Opening asks `+\chk_vfo` first and names VFOA in every command
// when it answers 1. The Main/Sub layout (receive on Sub, transmit on Main,
// for the IC-9700 in satellite mode) needs VFO mode: `+F Sub hz` and
// `+F Main hz`, `+M Sub mode pb` and `+M Main mode pb`, reads `+f Sub` and
// `+f Main`, and no split; without VFO mode the link does not open, and says
// to start rigctld with -o.
//
// Opening: connect, read `+f`, then time `+F` with the frequency just read
// to its RPRT, ask `+n`, and (of a peer answering in the extended form)
// `+s`, whether split is on already; then Open. The latency is the set's, not the
// read's: Hamlib answers get_freq from its cache (500 ms by default)
// without a byte to the radio, while a set always reaches the radio, and
// above 100 MHz Hamlib reads the frequency back before it answers
// (rig_set_freq), so a set's round trip is the command-to-read-back the
// Doppler steering lives with. The dummy rig shows the difference: `f` in
// 0.1 ms, `F` in 40 ms. Setting the frequency the radio just reported
// changes nothing on it. A tuning step of 0 (none set) or a refused get_ts
// (a backend without it answers RPRT -11) leaves the step at 1 Hz.
//
// Commands are paced (commandpacer.h). Commands given while the link is not
// open are refused through commandFailed(). A refusal (`RPRT -9`) or a bad
// value in a well-formed answer (`Frequency: nan`) is reported through
// commandFailed() and changes nothing. An answer that fits no form, a line
// past kMaxLineBytes, words nobody asked for, or silence past the reply
// timeout (10 s unless set) cannot be matched to commands any more: the
// link closes with the reason. A lost connection closes it too; reopening
// is the owner's, with open(). Reads ask the transmit frequency only once
// split was turned on over this connection.

#include "commandpacer.h"
#include "radiolink.h"
#include "rigctldreply.h"

#include <QElapsedTimer>
#include <QTcpSocket>
#include <QTimer>

#include <memory>
#include <optional>

namespace slew::radio {

class RigctldRadioLink : public RadioLink {
    Q_OBJECT
public:
    static constexpr quint16 kDefaultPort = 4532;
    static constexpr int kConnectTimeoutMs = 5000;
    // Above Hamlib's own give-up time for a silent radio (its timeout times
    // its retries, a few seconds), so a slow radio's RPRT -5 comes first.
    static constexpr int kDefaultReplyTimeoutMs = 10000;
    static constexpr qsizetype kMaxLineBytes = 256;
    // What Slew tunes: from 1 Hz to 1 THz (a 10 GHz transverter's too).
    static constexpr double kMinHz = 1;
    static constexpr double kMaxHz = 1e12;

    RigctldRadioLink(QString uri, QString host, quint16 port, QObject *parent = nullptr);
    ~RigctldRadioLink() override;

    void open() override;
    void close() override;
    State state() const override { return m_state; }
    QString uri() const override { return m_uri; }

    void setReceiveHz(double hz) override;
    void setTransmitHz(double hz) override;
    void setSplit(bool on) override;
    void setMode(const QString &mode, int passbandHz) override;
    void setTransmitMode(const QString &mode, int passbandHz) override;
    void readFrequencies() override;
    QString setVfoLayout(VfoLayout layout) override;
    VfoLayout vfoLayout() const override { return m_layout; }
    // rigctld was started in VFO mode (-o): every command names its VFO.
    bool inVfoMode() const { return m_vfoMode; }

    double tuningStepHz() const override { return m_tuningStepHz; }
    int latencyMs() const override { return m_latencyMs; }
    void setMinimumIntervalMs(int ms) override { m_pacer.setMinimumIntervalMs(ms); }
    void dropWaiting() override { m_pacer.dropWaiting(); }
    // How long a command may go unanswered before the link gives up on it.
    void setReplyTimeoutMs(int ms) { m_replyTimeoutMs = qMax(ms, 1); }

    QString host() const { return m_host; }
    quint16 port() const { return m_port; }

    // For tests and the traffic view: what the pacer holds.
    const CommandPacer &pacer() const { return m_pacer; }

private:
    // What each exchange is, carried through the pacer as its tag.
    enum class Exchange {
        OpeningVfoMode,
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

    RigctldReply replyFor(Exchange exchange, RigctldReply::Form form) const;
    void submit(CommandKind kind, Exchange exchange, const QString &text);
    void submitMode(CommandKind kind, Exchange exchange, const QString &verb, const QString &mode, int passbandHz);
    // A command line: `+F 145800000`, or in VFO mode `+F VFOA 145800000`
    // (`+F Sub 145800000` for the receive path with Main/Sub).
    enum class Path { Receive, Transmit };
    QString line(const char *verb, Path path, const QString &arguments = {}) const;
    // The answer to \chk_vfo: one line of its own, in no form of RigctldReply's.
    void takeVfoModeAnswer(QByteArrayView line);
    bool acceptFrequency(const QString &command, double hz);
    void send(const PacedCommand &command);
    void onConnected();
    void onSocketError();
    void onReadyRead();
    void onDeadline();
    void takeLine(QByteArrayView line);
    void finishExchange(const PacedCommand &command, const RigctldReply &reply);
    void becomeOpen();
    void setState(State state, const QString &detail);
    // Closes with the reason; the command on the wire, if any, failed with it.
    void fail(const QString &reason);

    QString m_uri;
    VfoLayout m_layout = VfoLayout::Split;
    bool m_vfoMode = false;
    QString m_host;
    quint16 m_port;
    QTcpSocket m_socket;
    CommandPacer m_pacer;
    QTimer m_deadline; // for the connection, then for each answer
    QElapsedTimer m_sentAt;
    std::unique_ptr<RigctldReply> m_reply; // the answer being read, while a command is out
    RigctldReply::Form m_peerForm = RigctldReply::Form::Either; // as its first answer showed
    State m_state = State::Closed;
    bool m_connected = false; // this connection got as far as connected()
    std::optional<double> m_receiveRead; // a read's first half, until its second comes
    bool m_splitOn = false;              // as the radio last accepted
    double m_tuningStepHz = 1.0;
    int m_latencyMs = 0;
    int m_replyTimeoutMs = kDefaultReplyTimeoutMs;
};

} // namespace slew::radio
