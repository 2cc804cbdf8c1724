// SPDX-License-Identifier: GPL-3.0-or-later
#include "transponder.h"

#include <cmath>

namespace slew::radio {

bool Transponder::isLinear() const
{
    return downlinkLowHz && downlinkHighHz && *downlinkLowHz != *downlinkHighHz;
}

bool Transponder::downlinkContains(double downlinkHz) const
{
    if (!downlinkLowHz || !std::isfinite(downlinkHz))
        return false;
    return downlinkHz >= *downlinkLowHz && downlinkHz <= *downlinkTopHz();
}

std::optional<double> Transponder::uplinkForDownlink(double downlinkHz) const
{
    if (!isLinear() || !uplinkLowHz || !downlinkContains(downlinkHz))
        return std::nullopt;
    if (inverting)
        return *uplinkLowHz + (*downlinkHighHz - downlinkHz);
    return *uplinkLowHz + (downlinkHz - *downlinkLowHz);
}

std::optional<double> Transponder::downlinkForUplink(double uplinkHz) const
{
    if (!isLinear() || !uplinkLowHz || !std::isfinite(uplinkHz))
        return std::nullopt;
    const double offset = uplinkHz - *uplinkLowHz;
    const double downlink = inverting ? *downlinkHighHz - offset : *downlinkLowHz + offset;
    if (!downlinkContains(downlink))
        return std::nullopt;
    return downlink;
}

QString Transponder::displayName() const
{
    return description.isEmpty() ? QStringLiteral("transponder") : description;
}

} // namespace slew::radio
