// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// SPID's binary frames: Rot2Prog, Rot1Prog, MD-01/02 (spidcodec.h). A set
// counts in the controller's pulses per degree, which only its replies
// tell: the codec reads them from the frames it has parsed.

#include "codec.h"

namespace slew::protocol {

class SpidFrameCodec final : public Codec {
public:
    SpidFrameCodec(Dialect d, int rotor) : Codec(d, rotor) {}

    // The MD-01/02's move frame; the others jog by set-position legs.
    bool jogsItself() const override { return supports(Op::MoveLeft); }
    bool stopHaltsEveryAxis() const override { return true; }
    bool readsTextLines() const override { return false; }
    Encoded setPosition(double azimuth, double elevation) const override;
    double setResolutionDeg() const override;
    Encoded jog(const std::array<double, 2> &degreesPerSecond, bool changedIsAzimuth) const override;
};

} // namespace slew::protocol
