// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A link to a radio, whatever carries it: Hamlib's rigctld over TCP
// (rigctldradio.h), libhamlib in process on a worker thread, or the rotator
// controller's own Easycomm UP/DN. The Doppler steering (dopplersteering.h)
// and the Radio panel speak to this interface only.
//
// Nothing here waits. Commands are paced on the link: one on the wire at a
// time, at most one waiting per kind (receive frequency, transmit
// frequency, mode, split), and a newer value replaces a waiting one, so a
// slow CAT bus skips stale frequencies and never builds a backlog; and a
// minimum interval between commands, per radio.

#include <QObject>
#include <QString>

#include <optional>

namespace slew::radio {

// Which of the radio's VFOs carry the two paths.
enum class VfoLayout {
    // Receive on VFOA, transmit on VFOB with split on (`S 1 VFOB`): most
    // radios, and Gpredict's way.
    Split,
    // Receive on Sub, transmit on Main: the IC-9700 and its kind in their
    // satellite mode (turned on at the radio), with no split.
    MainSub,
};

// What the radio holds, as last read back. Hertz.
struct RadioFrequencies {
    std::optional<double> receiveHz;
    std::optional<double> transmitHz; // the split VFO's, when split is on
};

class RadioLink : public QObject {
    Q_OBJECT
public:
    enum class State { Closed, Opening, Open };
    Q_ENUM(State)

    using QObject::QObject;
    ~RadioLink() override = default;

    virtual void open() = 0;
    virtual void close() = 0;
    virtual State state() const = 0;
    bool isOpen() const { return state() == State::Open; }
    // The URI it was made from, for messages.
    virtual QString uri() const = 0;

    // The newest value of each kind replaces one still waiting.
    virtual void setReceiveHz(double hz) = 0;
    virtual void setTransmitHz(double hz) = 0;
    // Receive on VFOA, transmit on VFOB (rigctld's `S 1 VFOB`).
    virtual void setSplit(bool on) = 0;
    // A Hamlib mode name (USB, LSB, CW, FM, ...) and passband (0: the radio's default).
    virtual void setMode(const QString &mode, int passbandHz) = 0;
    // The transmit side's mode with split on (rigctld's `X`, set_split_mode):
    // an inverting linear transponder takes LSB up and gives USB down.
    virtual void setTransmitMode(const QString &mode, int passbandHz) = 0;
    // Asks for both frequencies; frequenciesRead() follows.
    virtual void readFrequencies() = 0;
    // Forgets the commands not sent yet (the one on the wire finishes): a
    // pass that ends, or the operator's Stop of radio control, leaves
    // nothing of its own to reach the radio after it.
    virtual void dropWaiting() = 0;
    // Readings show the radio's own frequency, dial turns included: the
    // dial can be followed only where they do (a controller's UP/DN answers
    // say only what it was told).
    virtual bool canReadBack() const { return true; }

    // The VFOs the paths use, from the next opening on. Empty when the link
    // can use them; else why not (the link then keeps Split).
    virtual QString setVfoLayout(VfoLayout layout)
    {
        return layout == VfoLayout::Split ? QString() : tr("%1 has no Main and Sub VFOs to address").arg(uri());
    }
    virtual VfoLayout vfoLayout() const { return VfoLayout::Split; }

    // The radio's tuning step (Hz) where known, else 1.
    virtual double tuningStepHz() const { return 1.0; }
    // From a command to its read-back, measured when the link opened, or as
    // set; 0 until known.
    virtual int latencyMs() const { return 0; }
    // The least time between two commands on the wire (gpredict#181: some
    // buses need 20 ms).
    virtual void setMinimumIntervalMs(int ms) = 0;

signals:
    // `detail` names the link first ("rigctld://host:4532: cannot connect
    // ...": the operator may have more than one radio in mind), so whoever
    // shows it adds no name of its own; frequencies in it are as
    // frequencytext.h writes them.
    void stateChanged(slew::radio::RadioLink::State state, const QString &detail);
    void frequenciesRead(const slew::radio::RadioFrequencies &frequencies);
    // Each command as it went to the radio, for the traffic view and tests.
    void commandSent(const QString &command);
    // A command the radio refused or did not answer, with its words.
    void commandFailed(const QString &command, const QString &reason);
};

} // namespace slew::radio
