#pragma once
// What the firmware has seen, for tests and for the operator's log: how much
// it did and how much it refused, by reason.

#include <cstdint>

namespace slew::sim {

struct FirmwareCounters {
    std::uint64_t lines = 0;       // input lines ended by CR or LF
    std::uint64_t commands = 0;    // accepted commands and queries
    std::uint64_t unknown = 0;     // not a command of this dialect
    std::uint64_t malformed = 0;   // a known command with an unreadable argument
    std::uint64_t outOfLimits = 0; // an angle or register value the rotator refused
    std::uint64_t overlong = 0;    // tokens dropped for length
    std::uint64_t badChecksum = 0; // lines refused unread: wrong or missing `*HH` (checksum=1)
    // Bytes sent while a half-duplex line still carried the controller's
    // reply (firmware=satnogs: within 9 ms of it): never heard. Not counted
    // as rejected: the firmware did not see them to reject them.
    std::uint64_t lostInTurnaround = 0;

    std::uint64_t rejected() const { return unknown + malformed + outOfLimits + overlong + badChecksum; }
};

} // namespace slew::sim
