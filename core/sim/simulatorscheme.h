#pragma once
// Registers the `sim:` link scheme with the transport layer:
//
//   sim:?kp=30&ki=0&kd=2&az_max=450&el_max=90&dialect=satnogs&jam=az&clock=manual
//
// Every query item is a simulator option (simulatoroptions.h); a bad one
// makes createLink() fail with a message naming the URI and the item. The
// link's hints() say what the URI names of the rotator (az_max, el_max,
// park_az, park_el) and the dialect it speaks; its clockSeconds() is the
// simulator's clock.

#include <QString>

namespace slew::transport {
class Link;
}

namespace slew::sim {

class Simulator;

void registerSimulatorScheme();

// The simulator behind a link made from a `sim:` URI, for tests that step
// its clock, read its counters or switch faults; null for any other link.
Simulator *simulatorBehind(transport::Link *link);

} // namespace slew::sim
