// SPDX-License-Identifier: GPL-3.0-or-later
#include "operations.h"

#include <iterator>

namespace slew::protocol {

namespace {

using A = Argument;
using R = EasycommReach;

// Order matches enum Op so that a lookup is an index.
constexpr OperationInfo kOperations[] = {
    // op                   mnemonic  description               Easycomm                 GS-232 rotctld micro2g argument         command only
    {Op::Invalid,           "",       "unreadable input",       R::None,                 false, false,  false,   A::NeverSent,     false},
    {Op::Azimuth,           "AZ",     "azimuth",                R::All,                  true,  true,   true ,   A::Angle,         false},
    {Op::Elevation,         "EL",     "elevation",              R::All,                  true,  true,   false,   A::Angle,         false},
    {Op::UplinkFreq,        "UP",     "uplink frequency",       R::All,                  false, false,  false,   A::Integer,       false},
    {Op::DownlinkFreq,      "DN",     "downlink frequency",     R::All,                  false, false,  false,   A::Integer,       false},
    {Op::UplinkMode,        "UM",     "uplink mode",            R::All,                  false, false,  false,   A::Word,          false},
    {Op::DownlinkMode,      "DM",     "downlink mode",          R::All,                  false, false,  false,   A::Word,          false},
    {Op::UplinkRadio,       "UR",     "uplink radio",           R::FromEasycomm2,        false, false,  false,   A::Integer,       false},
    {Op::DownlinkRadio,     "DR",     "downlink radio",         R::FromEasycomm2,        false, false,  false,   A::Integer,       false},
    {Op::MoveLeft,          "ML",     "move left",              R::FromEasycomm2,        true,  true,   false,   A::None,          true},
    {Op::MoveRight,         "MR",     "move right",             R::FromEasycomm2,        true,  true,   false,   A::None,          true},
    {Op::MoveUp,            "MU",     "move up",                R::FromEasycomm2,        true,  true,   false,   A::None,          true},
    {Op::MoveDown,          "MD",     "move down",              R::FromEasycomm2,        true,  true,   false,   A::None,          true},
    {Op::StopAzimuth,       "SA",     "stop azimuth",           R::FromEasycomm2,        true,  true,   true ,   A::None,          true},
    {Op::StopElevation,     "SE",     "stop elevation",         R::FromEasycomm2,        true,  true,   false,   A::None,          true},
    {Op::Aos,               "AO",     "acquisition of signal",  R::FromEasycomm2,        false, false,  false,   A::None,          true},
    {Op::Los,               "LO",     "loss of signal",         R::FromEasycomm2,        false, false,  false,   A::None,          true},
    {Op::SetOutput,         "OP",     "set output",             R::FromEasycomm2,        false, false,  false,   A::OutputValue,   true},
    {Op::ReadInput,         "IP",     "input",                  R::FromEasycomm2,        false, false,  false,   A::Index,         false},
    {Op::ReadAnalog,        "AN",     "analogue input",         R::FromEasycomm2,        false, false,  false,   A::Index,         false},
    {Op::Time,              "ST",     "time",                   R::FromEasycomm2,        false, false,  false,   A::Word,          false},
    {Op::Version,           "VE",     "version",                R::FromEasycomm2,        false, true,   true ,   A::Word,          false},
    {Op::VelocityLeft,      "VL",     "velocity left",          R::Easycomm3AndSatNogs,  false, false,  false,   A::Velocity,      false},
    {Op::VelocityRight,     "VR",     "velocity right",         R::Easycomm3AndSatNogs,  false, false,  false,   A::Velocity,      false},
    {Op::VelocityUp,        "VU",     "velocity up",            R::Easycomm3AndSatNogs,  false, false,  false,   A::Velocity,      false},
    {Op::VelocityDown,      "VD",     "velocity down",          R::Easycomm3AndSatNogs,  false, false,  false,   A::Velocity,      false},
    {Op::ConfigRead,        "CR",     "config read",            R::Easycomm3AndSatNogs,  false, false,  false,   A::Register,      false},
    {Op::ConfigWrite,       "CW",     "config write",           R::Easycomm3AndSatNogs,  false, false,  false,   A::RegisterValue, true},
    // GS-232 too (the easycom library's table), answered `ST=n` (docs/protocol.md).
    {Op::Status,            "GS",     "status register",        R::Easycomm3AndSatNogs,  true,  false,  false,   A::Integer,       false},
    {Op::ErrorFlags,        "GE",     "error register",         R::Easycomm3AndSatNogs,  false, false,  false,   A::Integer,       false},
    // Hamlib sends RESET and PARK to models 202 and 204 alike.
    {Op::Reset,             "RESET",  "reset and home",         R::FromEasycomm2,        false, true,   false,   A::None,          true},
    {Op::Park,              "PARK",   "park",                   R::FromEasycomm2,        false, true,   false,   A::None,          true},
    {Op::Encoders,          "\\?ENC", "raw encoders",           R::Easycomm3Only,        false, false,  false,   A::None,          false},
    {Op::Alarm,             "AL",     "alarm",                  R::None,                 false, false,  false,   A::NeverSent,     false},
    {Op::ConfigValue,       "",       "config value",           R::None,                 false, false,  false,   A::NeverSent,     false},
    {Op::Speed,             "X",      "speed",                  R::None,                 true,  false,  false,   A::NeverSent,     false},
    // GS-232 only, as in the easycom library's table; the session sends it
    // while polling is paused, and the simulator answers `OK`.
    {Op::KeepAlive,         "?",      "keep-alive",             R::None,                 true,  false,  false,   A::None,          false},
    // GS-232's relative move, as in the easycom library's table. The
    // session's own relative move sends an absolute W instead
    // (docs/protocol.md); a raw `O` line is gated against the last position.
    {Op::Offset,            "O",      "relative move",          R::None,                 true,  false,  false,   A::NeverSent,     true},
    // The Micro-2g program's own commands (its header comment): the rotor
    // is the message's index. Its heading query and go-to are Azimuth, its
    // stop StopAzimuth, its `?` Version.
    {Op::SelectRotor,       "",       "select rotor",           R::None,                 false, false,  true ,   A::NeverSent,     true},
    {Op::Preset,            "P",      "go to preset",           R::None,                 false, false,  true ,   A::NeverSent,     true},
    {Op::StorePreset,       "L",      "store preset",           R::None,                 false, false,  true ,   A::NeverSent,     true},
    {Op::Tolerance,         "T",      "tolerance",              R::None,                 false, false,  true ,   A::NeverSent,     false},
    {Op::Calibration,       "Z",      "calibration",            R::None,                 false, false,  true ,   A::NeverSent,     false},
    {Op::AdcReadings,       "V",      "A/D readings",           R::None,                 false, false,  true ,   A::NeverSent,     false},
    {Op::RelayBits,         "R",      "relay bits",             R::None,                 false, false,  true ,   A::NeverSent,     false},
    // rotctld's answer to a command: `RPRT 0` when done (an error code
    // arrives as an alarm, see parser_rotctld.cpp).
    {Op::Report,            "RPRT",   "rotctld report",         R::None,                 false, false,  false,   A::NeverSent,     false},
    {Op::Refused,           "",       "refusal",                R::None,                 false, false,  false,   A::NeverSent,     false},
};
static_assert(std::size(kOperations) == size_t(Op::Refused) + 1, "kOperations must list every Op");

constexpr bool inOrder()
{
    for (size_t i = 0; i < std::size(kOperations); ++i) {
        if (size_t(kOperations[i].op) != i)
            return false;
    }
    return true;
}
static_assert(inOrder(), "kOperations must be in the order of enum Op");

} // namespace

const OperationInfo &operationInfo(Op op)
{
    return kOperations[size_t(op)];
}

QByteArrayView mnemonic(Op op)
{
    return QByteArrayView(operationInfo(op).mnemonic);
}

const char *describe(Op op)
{
    return operationInfo(op).description;
}

} // namespace slew::protocol
