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
// Opening: connect, ask `+\chk_vfo`, then the exchange script's opening
// (scriptedradiolink.h): read `+f`, time `+F` with the frequency just read
// to its RPRT, ask `+n`, and (of a peer answering in the extended form)
// `+s`, whether split is on already. The dummy rig shows why the set is
// timed and not the read (radiolimits.h): `f` in 0.1 ms, `F` in 40 ms.
//
// The script paces, checks and gives up (scriptedradiolink.h); the wire is
// rigctldperformer.h's. A refusal (`RPRT -9`) or a bad value in a
// well-formed answer (`Frequency: nan`) is reported through
// commandFailed() and changes nothing. An answer that fits no form, a line
// past kMaxLineBytes, words nobody asked for, or silence past the reply
// timeout cannot be matched to commands any more: the link closes with the
// reason. A lost connection closes it too.

#include "rigctldperformer.h"
#include "scriptedradiolink.h"

namespace slew::radio {

class RigctldRadioLink : public ScriptedRadioLink {
    Q_OBJECT
public:
    static constexpr quint16 kDefaultPort = 4532;

    RigctldRadioLink(QString uri, QString host, quint16 port, QObject *parent = nullptr);

    QString host() const { return rigctld().host(); }
    quint16 port() const { return rigctld().port(); }
    // rigctld was started in VFO mode (-o): every command names its VFO.
    bool inVfoMode() const { return rigctld().inVfoMode(); }

private:
    const RigctldPerformer &rigctld() const { return static_cast<const RigctldPerformer &>(performer()); }
};

} // namespace slew::radio
