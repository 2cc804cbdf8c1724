// SPDX-License-Identifier: GPL-3.0-or-later
#include "trackingnow.h"

#include "tracking/passrunner.h"

namespace slew::station {

face::TrackingNow trackingNow(const tracking::PassRunner *runner)
{
    using face::TrackingNow;
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

} // namespace slew::station
