// SPDX-License-Identifier: GPL-3.0-or-later
#include "connectionplan.h"

#include "model/savedcalibration.h"
#include "protocol/firmware.h"
#include "transport/linkfactory.h"

#include <QObject>

namespace slew::session {

namespace {

// The firmware a link names, where it can speak the profile's dialect; a
// firmware named for another dialect says nothing of this one.
void takeFirmware(model::RotatorProfile &profile, const transport::LinkHints &hints)
{
    if (const auto firmware = protocol::firmwareFromName(hints.firmware))
        profile.firmware = *firmware;
    if (!protocol::firmwareDialectConflict(profile.firmware, profile.dialect).isEmpty())
        profile.firmware = protocol::Firmware::Generic;
}

} // namespace

model::RotatorProfile profileWithHints(model::RotatorProfile profile, const transport::LinkHints &hints)
{
    model::RotatorProfile hinted = profile;
    if (const auto dialect = protocol::dialectFromName(hints.dialect))
        hinted.dialect = *dialect;
    takeFirmware(hinted, hints);
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
        profile.firmware = hinted.firmware;
        return profile;
    }
    return hinted;
}

QString hintNamesProblem(const transport::LinkHints &hints)
{
    if (!hints.dialect.isEmpty() && !protocol::dialectFromName(hints.dialect))
        return QObject::tr("unknown dialect '%1' (known: %2)").arg(hints.dialect, protocol::dialectNameList());
    const auto firmware = protocol::firmwareFromName(hints.firmware);
    if (!hints.firmware.isEmpty() && !firmware)
        return QObject::tr("unknown firmware '%1' (known: %2)").arg(hints.firmware, protocol::firmwareNameList());
    // Both named, and they do not go together: a slip the operator should
    // hear of, not a firmware quietly dropped.
    if (const auto dialect = protocol::dialectFromName(hints.dialect); dialect && firmware)
        return protocol::firmwareDialectConflict(*firmware, *dialect);
    return {};
}

model::RotatorProfile windowConnectionProfile(const QString &uri, model::RotatorProfile current,
                                              protocol::Dialect chosen, const QString &connectedBefore)
{
    model::RotatorProfile profile = std::move(current);
    profile.uri = uri;
    profile.dialect = chosen;
    // What the link says of its far end (a simulator's URI names the
    // rotator and its dialect); hardware says nothing and the profile stands,
    // but for a firmware the URI names (`serial:/dev/ttyUSB0?firmware=k3ng`)
    // or the profile held, where it can speak the dialect chosen: SatNOGS's
    // quirks never ride a GS-232 link.
    if (const transport::LinkHints hints = transport::linkHintsFor(uri); !hints.dialect.isEmpty())
        profile = profileWithHints(profile, hints);
    else
        takeFirmware(profile, hints);
    if (const auto saved = model::savedCalibration(uri)) {
        profile.azOffsetDeg = saved->azDeg;
        profile.elOffsetDeg = saved->elDeg;
    } else if (uri != connectedBefore && !connectedBefore.isEmpty()) {
        profile.azOffsetDeg = profile.elOffsetDeg = 0.0;
    }
    return profile;
}

protocol::Dialect probeDialect(const QString &uri, protocol::Dialect chosen)
{
    return protocol::dialectFromName(transport::linkHintsFor(uri).dialect).value_or(chosen);
}

model::RotatorProfile commandLineConnectionProfile(model::RotatorProfile profile, bool operatorNamedDialect)
{
    const transport::LinkHints hints = transport::linkHintsFor(profile.uri);
    const auto dialect = protocol::dialectFromName(hints.dialect);
    if (dialect && (hints.dialectFixed || !operatorNamedDialect))
        profile.dialect = *dialect;
    takeFirmware(profile, hints);
    return profile;
}

} // namespace slew::session
