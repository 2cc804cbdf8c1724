// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One table of what each operation is: its Easycomm mnemonic, which dialects
// send it (the Easycomm flavours, GS-232, rotctld, Micro-2g), what follows the mnemonic on the wire, and whether it is a bare
// command that no controller answers with a value. The encoder, the dialect
// checks and the session's echo filter all read this table; docs/protocol.md
// has a row for every entry.

#include "message.h"

#include <cstdint>

namespace slew::protocol {

// The Easycomm dialects that send an operation (GS-232 is a column of its own).
enum class EasycommReach : std::uint8_t {
    None,             // not sent by the host in any Easycomm dialect
    All,              // Easycomm I to III and SatNOGS (Easycomm I inside its one line)
    FromEasycomm2,    // Easycomm II, III and SatNOGS
    Easycomm3AndSatNogs,
    Easycomm3Only,
};

// What follows the mnemonic in an Easycomm token.
enum class Argument : std::uint8_t {
    None,          // ML, SA, PARK, \?ENC
    Angle,         // AZ180.00: decimals per dialect
    Integer,       // UP145800000, GS3
    Word,          // UMFM, VE1.0
    Velocity,      // VL050 (mdeg/s, padded per dialect)
    OutputValue,   // OP2,1
    Index,         // IP3
    Register,      // CR1 (SatNOGS: CR 1)
    RegisterValue, // CW1,0.800
    NeverSent,     // a reply (AL, n,value) or a GS-232-only command
};

struct OperationInfo {
    Op op;
    const char *mnemonic;    // as on the wire; empty when there is none
    const char *description; // for people
    EasycommReach easycomm;
    bool gs232;              // GS-232 A/B has a command for it (docs/protocol.md)
    bool rotctld;            // rotctld has a command for it (the encoder writes its form)
    bool micro2g;            // the Micro-2g program has a command for it (docs/protocol.md)
    Argument argument;
    bool commandOnly;        // never answered with a value: an echo of it is only an echo
};

const OperationInfo &operationInfo(Op op);

} // namespace slew::protocol
