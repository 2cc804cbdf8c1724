// SPDX-License-Identifier: GPL-3.0-or-later
#include "firmware.h"

#include <QObject>

#include <array>

namespace slew::protocol {

namespace {

struct FirmwareEntry {
    Firmware firmware;
    const char *name;
    const char *title;
    FirmwareTraits traits;
};

// K3NG's defaults are its settings.h (AZIMUTH_TOLERANCE, ELEVATION_TOLERANCE).
// SatNOGS v2.2: 19200 baud over RS485; its reply keeps the bus for about
// 9 ms after the last byte, so 10 ms clears it. A position every 200 ms and
// telemetry every 3 s: eight lines a second, half of what slowed its
// steppers by a seventh (docs/protocol.md says what was measured).
const std::array<FirmwareEntry, 3> kFirmware{{
    {Firmware::Generic, "generic", "as documented", {}},
    {Firmware::K3ng, "k3ng", "K3NG rotator controller", {3.0, 0.1, true, true, false, 0, 0, 0}},
    {Firmware::SatNogs, "satnogs", "SatNOGS rotator firmware", {0.0, 0.0, false, false, true, 10, 200, 3000}},
}};

const FirmwareEntry &entry(Firmware firmware)
{
    for (const FirmwareEntry &e : kFirmware)
        if (e.firmware == firmware)
            return e;
    return kFirmware[0];
}

} // namespace

Firmware firmwareOf(Dialect dialect, Firmware declared)
{
    return dialect == Dialect::SatNogs ? Firmware::SatNogs : declared;
}

const FirmwareTraits &firmwareTraits(Firmware firmware)
{
    return entry(firmware).traits;
}

QString firmwareName(Firmware firmware)
{
    return QString::fromLatin1(entry(firmware).name);
}

std::optional<Firmware> firmwareFromName(QStringView name)
{
    for (const FirmwareEntry &e : kFirmware)
        if (name.compare(QLatin1String(e.name), Qt::CaseInsensitive) == 0)
            return e.firmware;
    return std::nullopt;
}

QString firmwareNameList()
{
    QStringList names;
    for (const FirmwareEntry &e : kFirmware)
        names << QString::fromLatin1(e.name);
    return names.join(QStringLiteral(", "));
}

QString firmwareTitle(Firmware firmware)
{
    return QString::fromLatin1(entry(firmware).title);
}

QString firmwareDialectConflict(Firmware firmware, Dialect dialect)
{
    switch (firmware) {
    case Firmware::Generic:
        return {};
    case Firmware::K3ng:
        if (dialect == Dialect::Easycomm2 || isGs232(dialect))
            return {};
        return QObject::tr("k3ng speaks easycomm2, gs232a or gs232b, not %1").arg(dialectName(dialect));
    case Firmware::SatNogs:
        if (dialect == Dialect::SatNogs)
            return {};
        return QObject::tr("satnogs firmware speaks the satnogs dialect, not %1").arg(dialectName(dialect));
    }
    return {};
}

} // namespace slew::protocol
