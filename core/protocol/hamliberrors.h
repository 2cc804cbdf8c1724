// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Hamlib's error codes (enum rig_errcode_e in Hamlib's rig.h), which rotctld
// sends negated after RPRT: `RPRT -9` is RIG_ERJCTED. One table, read by the
// rotctld parser (a peer's refusal) and by Slew's own rotctld server (its
// answers and their descriptions).

namespace slew::protocol {

enum class HamlibError : int {
    Ok = 0,
    InvalidArgument = 1, // RIG_EINVAL
    Timeout = 5,         // RIG_ETIMEOUT
    Io = 6,              // RIG_EIO
    Protocol = 8,        // RIG_EPROTO
    Rejected = 9,        // RIG_ERJCTED
    NotAvailable = 11,   // RIG_ENAVAIL
    Limit = 21,          // RIG_ELIMIT
};

// "RIG_ERJCTED" for 9 or -9; nullptr for a code Hamlib does not define.
const char *hamlibErrorName(int code);
// "command rejected" for 9 or -9; nullptr for a code Hamlib does not define.
const char *hamlibErrorText(int code);

} // namespace slew::protocol
