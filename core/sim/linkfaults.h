#pragma once
// Faults of the line between host and simulator, as opposed to the rotator's
// own: a slow line, a lossy or noisy one, and one that goes away.

namespace slew::sim {

struct LinkFaults {
    double latency = 0.0;     // seconds before every reply leaves
    double dropRate = 0.0;    // share of reply bytes that are lost, 0..1
    double garbageRate = 0.0; // share of reply bytes followed by a random byte, 0..1
    // Share of reply lines with one bit of one byte flipped, 0..1: the line
    // keeps its length and usually still reads (`AZ10.0` becomes `AZ11.0`),
    // which only a checksum catches. 1 damages every line, for tests.
    double corruptRate = 0.0;
    double dropAfter = 0.0;   // a connection is cut this many seconds after it opened; 0 never

    friend bool operator==(const LinkFaults &, const LinkFaults &) = default;
};

} // namespace slew::sim
