// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Text lines: Easycomm I-III and SatNOGS, GS-232A/B, rotctld and Micro-2g
// (encoder.h writes them, parser.h reads them).

#include "codec.h"

namespace slew::protocol {

class LineCodec final : public Codec {
public:
    LineCodec(Dialect d, int rotor) : Codec(d, rotor) {}

    bool jogsItself() const override;
    bool stopHaltsEveryAxis() const override { return false; }
    bool readsTextLines() const override { return true; }
    Encoded setPosition(double azimuth, double elevation) const override;
    double setResolutionDeg() const override;
    Encoded jog(const std::array<double, 2> &degreesPerSecond, bool changedIsAzimuth) const override;
    QString rawLineRefusal(const Message &m) const override;
    bool azimuthIsBearing() const override { return row().family == DialectFamily::Micro2g; }
};

} // namespace slew::protocol
