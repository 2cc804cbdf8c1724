// SPDX-License-Identifier: GPL-3.0-or-later
#include "profilehints.h"

#include "protocol/dialect.h"

namespace slew::session {

model::RotatorProfile profileWithHints(model::RotatorProfile profile, const transport::LinkHints &hints)
{
    model::RotatorProfile hinted = profile;
    if (const auto dialect = protocol::dialectFromName(hints.dialect))
        hinted.dialect = *dialect;
    if (hints.azMax)
        hinted.limits.azMax = *hints.azMax;
    if (hints.elMax)
        hinted.limits.elMax = *hints.elMax;
    if (hints.parkAz)
        hinted.parkAz = *hints.parkAz;
    if (hints.parkEl)
        hinted.parkEl = *hints.parkEl;
    // All or nothing past the dialect: half a rotator's travel is worse
    // than the operator's own profile.
    if (!hinted.validate().isEmpty()) {
        profile.dialect = hinted.dialect;
        return profile;
    }
    return hinted;
}

} // namespace slew::session
