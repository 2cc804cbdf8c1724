// SPDX-License-Identifier: GPL-3.0-or-later
#include "trackingnow.h"

#include "tracking/passrunner.h"

namespace slew::station {

TrackingNow trackingNow(const tracking::PassRunner *runner)
{
    TrackingNow now;
    if (!runner || !runner->isRunning())
        return now;
    switch (runner->tracker().state()) {
    case tracking::Tracker::State::Waiting:
        now.phase = TrackingNow::Phase::Waiting;
        break;
    case tracking::Tracker::State::Tracking:
        now.phase = TrackingNow::Phase::Tracking;
        break;
    case tracking::Tracker::State::Done:
        now.phase = TrackingNow::Phase::Done;
        break;
    default:
        now.phase = TrackingNow::Phase::Planning;
    }
    now.target = runner->target().name();
    if (runner->target().kind == tracking::TrackTarget::Kind::Satellite && runner->target().elements.catalogueNumber > 0)
        now.norad = runner->target().elements.catalogueNumber;
    now.pass = runner->pass();
    return now;
}

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

} // namespace slew::station
