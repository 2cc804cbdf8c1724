// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one exchange script of a radio link that reads its radio back: what
// is asked of the radio, in what order, what its answers mean, and when
// the link gives up on it. The backend under it only performs single
// exchanges (exchangeperformer.h): rigctld over TCP (rigctldradio.h),
// libhamlib on a worker thread (hamlibradio.h). Its limits are
// radiolimits.h's.
//
// Opening: the performer reaches the radio; then the receive frequency is
// read, set back unchanged to time the round trip (the latency), the
// tuning step is asked, and with the Split layout whether split is on
// already (where the backend can ask it); then Open, the detail naming
// the frequency read.
//
// Commands are paced (commandpacer.h): one on the wire, the newest of each
// kind replacing a waiting one. A value outside the limits, or one the
// backend cannot send, is refused through commandFailed() and nothing is
// sent, as is any command while the link is not open.
//
// A refusal, or a reading that is no number in range, is reported through
// commandFailed() with the backend's words and changes nothing. The link
// closes, with the reason, when the radio is gone: the performer lost it
// (a connection lost, a stream that cannot be followed), an I/O or
// protocol error, a timeout kTimeoutsBeforeClosing times in a row, or a
// command unanswered for the reply timeout. Reopening is the owner's, with
// open(). A read asks the transmit frequency too when split is on (found
// at opening or turned on since), and always with Main/Sub.
//
// The receive frequency is read last, the reading is told while the read
// still holds the wire, and a receive frequency goes ahead of anything
// waiting: a frequency sent in answer to a reading then follows it at
// once. CAT has no lock, and a turn of the radio's dial that lands between
// the reading and that frequency is overwritten unseen; this keeps that
// window to one round trip.

#include "commandpacer.h"
#include "exchangeperformer.h"
#include "radiolink.h"

#include <QElapsedTimer>
#include <QTimer>

#include <map>
#include <memory>
#include <optional>

namespace slew::radio {

class ScriptedRadioLink : public RadioLink {
    Q_OBJECT
public:
    ScriptedRadioLink(QString uri, std::unique_ptr<ExchangePerformer> performer, QObject *parent = nullptr);
    ~ScriptedRadioLink() override;

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
    void dropWaiting() override { m_pacer.dropWaiting(); }

    // Both backends name each command's VFO: the layout is taken at the
    // next opening, where the backend may still refuse it.
    QString setVfoLayout(VfoLayout layout) override;
    VfoLayout vfoLayout() const override { return m_wantedLayout; }

    double tuningStepHz() const override { return m_tuningStepHz; }
    int latencyMs() const override { return m_latencyMs; }
    void setMinimumIntervalMs(int ms) override { m_pacer.setMinimumIntervalMs(ms); }
    // How long a command may go unanswered before the link gives up on it
    // (limits::kReplyTimeoutMs unless set).
    void setReplyTimeoutMs(int ms) { m_replyTimeoutMs = qMax(ms, 1); }

    // For tests and the traffic view: what the pacer holds.
    const CommandPacer &pacer() const { return m_pacer; }

protected:
    ExchangePerformer &performer() const { return *m_performer; }

private:
    // Where a command stands in the script, carried through the pacer as its tag.
    // A read (Read) starts with the transmit frequency where it is read,
    // as the link stands when the read goes, and ends with ReadReceive.
    enum class Step { OpeningRead, OpeningLatency, OpeningStep, OpeningSplit, Set, Read, ReadReceive };

    // The URI as messages start with it, without a colon of its own at the
    // end ("sim: closed", not "sim:: closed").
    QString label() const;
    bool acceptFrequency(const RadioCommand &command);
    bool acceptMode(const RadioCommand &command);
    enum class Place { InLine, First };
    void submit(CommandKind kind, const RadioCommand &command, Place place = Place::InLine);
    PacedCommand paced(Step step, CommandKind kind, const RadioCommand &command) const;
    RadioCommand commandFor(const PacedCommand &paced) const;
    bool readsTransmit() const;
    void onOpened();
    void onReady(const PacedCommand &paced);
    void onAnswered(const RadioAnswer &answer);
    void onDeadline();
    // What one answer leads to.
    struct Outcome {
        QString failure; // for commandFailed(): why this command did nothing
        std::optional<PacedCommand> next;
        std::optional<RadioFrequencies> read;
        bool opened = false;
    };
    void finishExchange(const PacedCommand &command, const RadioAnswer &answer);
    void takeOpeningAnswer(Step step, const RadioAnswer &answer, Outcome &outcome);
    void takeAnswer(Step step, const RadioCommand &performed, const RadioAnswer &answer, Outcome &outcome);
    // True when this answer says the radio is gone; counts the timeouts.
    bool givesUp(int code);
    void becomeOpen();
    void setState(State state, const QString &detail);
    // Closes with the reason; the command on the wire, if any, failed with it.
    void fail(const QString &reason);

    const QString m_uri;
    const std::unique_ptr<ExchangePerformer> m_performer;
    CommandPacer m_pacer;
    QTimer m_deadline; // for the answer to the command on the wire
    QElapsedTimer m_sentAt;
    int m_replyTimeoutMs;
    State m_state = State::Closed;
    VfoLayout m_wantedLayout = VfoLayout::Split; // from the next opening on
    VfoLayout m_layout = VfoLayout::Split;       // this opening's
    // The pacer carries a command's text and tag only: the newest command
    // of each kind given, which is the one the pacer holds waiting.
    std::map<CommandKind, RadioCommand> m_newest;
    RadioCommand m_onTheWire;
    std::optional<double> m_receiveRead;  // the opening's reading
    std::optional<double> m_transmitRead; // a read's first half, until its second comes
    int m_openings = 0;                   // open() calls: an answer's handlers may close and reopen
    bool m_splitOn = false;              // as the radio last said or accepted
    int m_timeoutsInARow = 0;
    double m_tuningStepHz;
    int m_latencyMs = 0;
};

} // namespace slew::radio
