// SPDX-License-Identifier: GPL-3.0-or-later
#include "trackingnow.h"

#include "sky/skyvector.h"

#include <cmath>

namespace slew::face {

QString phaseWord(TrackingNow::Phase phase)
{
    switch (phase) {
    case TrackingNow::Phase::Planning:
        return QStringLiteral("planning");
    case TrackingNow::Phase::Waiting:
        return QStringLiteral("waiting");
    case TrackingNow::Phase::Tracking:
        return QStringLiteral("tracking");
    case TrackingNow::Phase::Done:
        return QStringLiteral("done");
    case TrackingNow::Phase::Off:
        break;
    }
    return QStringLiteral("off");
}

std::optional<TrackingNow::Phase> phaseFromWord(const QString &word)
{
    using Phase = TrackingNow::Phase;
    for (const Phase phase : {Phase::Off, Phase::Planning, Phase::Waiting, Phase::Tracking, Phase::Done}) {
        if (phaseWord(phase) == word)
            return phase;
    }
    return std::nullopt;
}

TrackingNow trackingOf(const StationState &state)
{
    TrackingNow now;
    now.phase = phaseFromWord(state.tracking).value_or(TrackingNow::Phase::Off);
    now.target = state.trackingTarget;
    now.norad = state.trackingNorad;
    if (state.passAosMs && state.passLosMs) {
        sky::Pass pass;
        pass.aos.julian = julianOfUnixMs(*state.passAosMs);
        pass.los.julian = julianOfUnixMs(*state.passLosMs);
        now.pass = pass;
    }
    return now;
}

double julianOfUnixMs(qint64 ms)
{
    return sky::julianFromUnixSeconds(double(ms) / 1000.0);
}

qint64 unixMsOfJulian(double julian)
{
    return qint64(std::llround((julian - 2440587.5) * 86400000.0));
}

} // namespace slew::face
