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
// rig_set_vfo is never called. Only what Hamlib can take reaches it
// (radiolimits.h): frequencies finite, 1 Hz to 1 THz, sent in whole hertz;
// a mode that rig_parse_mode knows; a passband from -1 (unchanged) to
// 1 MHz. Anything else is refused through commandFailed() and nothing is
// sent, as are commands while the link is not open.
//
// Opening: rig_open (a serial model's device, rate and CI-V address set
// first), then the exchange script's opening (scriptedradiolink.h):
// get_freq, set_freq with the frequency just read, timed from the moment
// it leaves this link to its result, get_ts, and with the Split layout
// get_split_vfo; then Open. The dummy rig takes about 40 ms for a set.
//
// The script paces, checks and gives up; the calls are
// hamlibperformer.h's. A call Hamlib refuses or fails reports
// commandFailed() with Hamlib's words and changes nothing. One that says
// the radio is gone closes the link with the reason: an I/O or protocol
// error, or a timeout twice in a row (Hamlib has retried each before
// giving up). A failed opening closes it too. Reopening is the owner's,
// with open().

#include "hamlibperformer.h"
#include "scriptedradiolink.h"

namespace slew::radio {

class HamlibRadioLink : public ScriptedRadioLink {
    Q_OBJECT
public:
    // uri() is the URI as given ("hamlib:3081?device=/dev/ttyUSB0"); "sim:" for the built-in radio.
    explicit HamlibRadioLink(HamlibRadioConfig config, QObject *parent = nullptr);

    const HamlibRadioConfig &config() const
    {
        return static_cast<const HamlibPerformer &>(performer()).config();
    }
    // Worker threads of any link, this one's or a destroyed one's, that
    // have not yet ended and been deleted.
    static int liveWorkers();
};

} // namespace slew::radio
