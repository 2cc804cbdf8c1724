// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Radio panel's frequencies kept per satellite in the settings, by NORAD
// number (0: for whatever satellite is tracked), as the operator wrote them:
// "145.8M" comes back as "145.8M", and is read again by the same rules when
// it is applied. A satellite tracked again gets its own frequencies and
// calibration offsets back.

#include <QString>

#include <optional>

namespace slew::ui {

struct RadioPlanTexts {
    QString downlink, uplink;             // parseFrequency's forms; the uplink may be empty
    QString receiveMode, transmitMode;    // Hamlib mode names; empty: left as the radio has it
    QString downlinkOffset, uplinkOffset; // parseFrequencyOffset's forms; empty: none
    QString doppler = QStringLiteral("both");     // parseDopplerOn's words
    QString uplinkFollows = QStringLiteral("no"); // parseUplinkFollows's words

    bool operator==(const RadioPlanTexts &) const = default;
};

// What was kept for `noradId`, if anything.
std::optional<RadioPlanTexts> keptRadioPlan(int noradId);
void keepRadioPlan(int noradId, const RadioPlanTexts &texts);

// The satellite whose frequencies were applied last (0: any), to show and
// apply at the next start; nothing before the first Apply.
std::optional<int> lastAppliedRadioPlan();

} // namespace slew::ui
