// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The final outcome of an intent asked of a station's face: the outcome
// itself when it is final (a station in this process), else the station's
// answer by the intent's id (one on a broker), waited for on the event
// loop. A test that drives a script through either kind of face reads
// both the same way.

#include "simulatorpump.h"

#include "face/stationface.h"

#include <optional>

inline slew::face::Outcome settledOutcome(slew::face::StationFace &face, const slew::face::Outcome &outcome,
                                          int timeoutMs = 15000)
{
    using slew::face::Outcome;
    if (!outcome.isAwaiting())
        return outcome;
    std::optional<Outcome> answer;
    const auto connection = QObject::connect(&face, &slew::face::StationFace::answered, &face,
                                             [&](const QString &id, const Outcome &o) {
                                                 if (id == outcome.id())
                                                     answer = o;
                                             });
    runEventLoopUntil([&] { return answer.has_value(); }, timeoutMs);
    QObject::disconnect(connection);
    return answer.value_or(Outcome::refused(QStringLiteral("no answer within %1 s").arg(timeoutMs / 1000)));
}
