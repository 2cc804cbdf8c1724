// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a radio link's backend does for the exchange script
// (scriptedradiolink.h): reach the radio, carry one command to it and
// bring back its answer, and let it go. rigctld over TCP
// (rigctldperformer.h) and libhamlib on a worker thread
// (hamlibperformer.h) are two; a test's fake is a third.
//
// A performer decides nothing: not what is asked next, nor whether an
// answer is usable, nor how long to wait for one, nor when to give up on
// the radio. It says what came back, in its backend's words.
//
// One command at a time: perform() is called only once the command before
// was answered. Every perform() is answered exactly once, by answered() or
// lost(), unless close() or abort() comes first; after either, nothing of
// that session is reported. A report may come from inside the call that
// caused it (a fake answers at once).

#include "radiolimits.h"
#include "radiolink.h"

#include <QObject>
#include <QString>

#include <cmath>
#include <optional>

namespace slew::radio {

enum class RadioPath { Receive, Transmit };

// One command, in the script's terms; the performer turns it into its
// backend's (`+F 145800000`, rig_set_freq) for the VFO layout it was
// opened with. The transmit path is the split VFO with the Split layout,
// Main with Main/Sub.
struct RadioCommand {
    enum class Call { ReadFrequency, SetFrequency, SetMode, SetSplit, ReadSplit, ReadStep };
    Call call = Call::ReadFrequency;
    RadioPath path = RadioPath::Receive;
    double hz = 0;       // SetFrequency
    QString mode;        // SetMode: a Hamlib mode name
    int passbandHz = 0;  // SetMode
    bool on = false;     // SetSplit
};

// What came back for one command.
struct RadioAnswer {
    int code = 0;                 // Hamlib's: 0 done, else a negative RIG_E... code
    QString why;                  // a refusal in the backend's words: "refused: RPRT -9 (command rejected)"
    std::optional<QString> value; // what a read answered, as text, unchecked
};

// A frequency as a command's text writes it: whole hertz when it is one
// Slew tunes, else as given, for the message that refuses it ("+F nan").
inline QString commandHzText(double hz)
{
    return limits::kFrequencyRange.contains(hz) ? QString::number(qint64(std::llround(hz))) : QString::number(hz);
}

class ExchangePerformer : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;
    ~ExchangePerformer() override = default;

    // What open() does, for the link's Opening detail: "connecting to 127.0.0.1:4532".
    virtual QString reaching() const = 0;
    // Reaches the radio, ready for commands with this layout: opened() or
    // lost() follows. How long that may take is the backend's (a TCP
    // connect, or a serial radio's open, which Hamlib gives 10 s and more).
    virtual void open(VfoLayout layout) = 0;
    // Carries one command: answered() or lost() follows.
    virtual void perform(const RadioCommand &command) = 0;
    // Ends the session in order (rigctld is told it is done).
    virtual void close() = 0;
    // Ends it at once: the link gave up on it.
    virtual void abort() = 0;

    // The command as the traffic view shows it: `+F 145800000`, `set_freq Sub 145800000`.
    virtual QString text(const RadioCommand &command) const = 0;
    // Why this backend cannot send a command the shared limits let through
    // (a mode name Hamlib does not know); empty when it can.
    virtual QString refusal(const RadioCommand &) const { return {}; }
    // Whether this session can ask if split is on (ReadSplit).
    virtual bool canReadSplit() const { return true; }
    // Who answers commands, for a message about silence: "rigctld".
    virtual QString peerName() const = 0;

signals:
    void opened();
    void answered(const slew::radio::RadioAnswer &answer);
    // The radio cannot be reached any more: why, without the link's name.
    void lost(const QString &reason);
    // Words the performer sent of its own accord (rigctld's \chk_vfo and
    // q), for the traffic view.
    void said(const QString &text);
};

} // namespace slew::radio
