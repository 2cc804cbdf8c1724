// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// libhamlib as a whole, as the in-process radio link (hamlibradio.h) needs
// it: the state Hamlib keeps for the process, set once, and what can be
// read from it without a radio.
//
// prepareHamlib() runs once per process, on the first call, before any
// link's worker thread exists (makeRadioLink and every HamlibRadioLink call
// it first). It silences Hamlib's debug output, which would otherwise go
// to the terminal; loads every backend, so that a model's capabilities can
// be looked up and rig_init() never loads one while another thread reads
// the table; and copies Hamlib's error words. rigerror2() writes them into
// a static buffer that Hamlib's own calls also write on the workers'
// threads, so it is read here once and never again.
//
// After that the tables read here are never written, and the functions
// below may run on any thread while workers talk to their radios.

#include <QString>

#include <optional>

namespace slew::radio {

void prepareHamlib();

// Hamlib's words for one of its error codes (negative or not), as
// rigerror2() gives them: "Communication timed out" for -RIG_ETIMEOUT.
QString hamlibErrorWords(int code);

// What Slew needs to know of a Hamlib radio model before opening it.
struct HamlibModel {
    int number = 0;
    QString name;               // "Icom IC-9700"
    bool serial = false;        // driven over a serial line (device=, baud=)
    bool hasCivAddress = false; // takes a CI-V address (civaddr=)
};

// The model, when Hamlib 4.5.4 knows its number; nothing otherwise.
std::optional<HamlibModel> hamlibModel(int number);

} // namespace slew::radio
