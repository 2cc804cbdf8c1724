// SPDX-License-Identifier: GPL-3.0-or-later
#include "hamliberrors.h"

#include <cstdint>
#include <iterator>

namespace slew::protocol {

namespace {

struct ErrorInfo {
    const char *name;
    const char *text;
};

// Indexed by the code. The texts are short, for a message that also names
// the command or the link.
constexpr ErrorInfo kErrors[] = {
    {"RIG_OK", "no error"},
    {"RIG_EINVAL", "invalid argument"},
    {"RIG_ECONF", "invalid configuration"},
    {"RIG_ENOMEM", "out of memory"},
    {"RIG_ENIMPL", "not implemented"},
    {"RIG_ETIMEOUT", "timed out"},
    {"RIG_EIO", "input/output error"},
    {"RIG_EINTERNAL", "internal error"},
    {"RIG_EPROTO", "protocol error"},
    {"RIG_ERJCTED", "command rejected"},
    {"RIG_ETRUNC", "argument truncated"},
    {"RIG_ENAVAIL", "not available"},
    {"RIG_ENTARGET", "target not reachable"},
    {"RIG_BUSERROR", "bus error"},
    {"RIG_BUSBUSY", "bus collision"},
    {"RIG_EARG", "null argument"},
    {"RIG_EVFO", "invalid VFO"},
    {"RIG_EDOM", "argument out of domain"},
    {"RIG_EDEPRECATED", "function deprecated"},
    {"RIG_ESECURITY", "security error"},
    {"RIG_EPOWER", "device powered off"},
    {"RIG_ELIMIT", "limit exceeded"},
    {"RIG_EACCESS", "access denied"},
};

const ErrorInfo *find(int code)
{
    // A peer's `RPRT n` can be any int; negating INT_MIN would overflow.
    const std::int64_t magnitude = code < 0 ? -std::int64_t(code) : std::int64_t(code);
    if (magnitude >= std::int64_t(std::size(kErrors)))
        return nullptr;
    return &kErrors[magnitude];
}

} // namespace

const char *hamlibErrorName(int code)
{
    const ErrorInfo *e = find(code);
    return e ? e->name : nullptr;
}

const char *hamlibErrorText(int code)
{
    const ErrorInfo *e = find(code);
    return e ? e->text : nullptr;
}

} // namespace slew::protocol
