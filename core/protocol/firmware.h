// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Which firmware runs in the controller, where the dialect does not say
// everything: the two families most stations run answer the same commands
// as the documents say, but stop, report and keep up in ways of their own
// (docs/protocol.md, "Controllers in the field"). Each quirk is written
// down here once; the session, the move watch and the simulator read it.

#include "dialect.h"

#include <QString>
#include <QStringView>

#include <cstdint>
#include <optional>

namespace slew::protocol {

enum class Firmware : std::uint8_t {
    Generic, // as the dialect's documents say (and Slew's simulator by default)
    K3ng,    // K3NG's Arduino rotator controller, Easycom (easycomm2) or Yaesu (gs232a, gs232b) emulation
    SatNogs, // the SatNOGS rotator firmware v2.x (dialect satnogs)
};

struct FirmwareTraits {
    // How close the controller itself brings each axis before it stops
    // driving: a move that ends this close has arrived (K3NG's
    // AZIMUTH_TOLERANCE and ELEVATION_TOLERANCE, 3.0° and 0.1° by default).
    double azToleranceDeg = 0.0;
    double elToleranceDeg = 0.0;
    // Whether a status word without the moving bit means the axes are at
    // rest. The SatNOGS firmware answers GS4 ("pointing") for a whole move
    // and never sets the moving bit, so only its position tells.
    bool statusShowsMotion = true;
    // Whether CR10/CR11 (the commanded position) exist. The SatNOGS firmware
    // reads only the first digit of a register number: asked CR10 it answers
    // register 1 (`1,8.00`).
    bool commandedRegisters = true;
    // Whether the controller obeys its dialect's PARK. K3NG's Easycom
    // emulation answers `?`: Slew parks it with a go-to to the profile's
    // park position, as on GS-232, which has no PARK.
    bool parkCommand = true;
    // How long the controller needs after its reply before it can hear the
    // next line: the half-duplex RS485 turn-around. A line sent sooner is lost.
    int turnaroundMs = 0;
    // The shortest poll interval, and the shortest time between two rounds
    // of telemetry (status, errors, inputs: nine lines), that do not starve
    // the firmware: each SatNOGS reply holds its main loop, and its
    // steppers, at least 9 ms (5.3°/s under 17 lines a second against
    // 6.2°/s unpolled). 200 ms and 3 s make eight lines a second.
    int shortestPollMs = 0;
    int telemetryEveryMs = 0;
};

// The firmware a controller of this dialect runs when the operator named
// `declared`: the SatNOGS dialect is the SatNOGS firmware's.
Firmware firmwareOf(Dialect dialect, Firmware declared);
const FirmwareTraits &firmwareTraits(Firmware firmware);

QString firmwareName(Firmware firmware); // "generic", "k3ng", "satnogs"
std::optional<Firmware> firmwareFromName(QStringView name);
QString firmwareNameList(); // "generic, k3ng, satnogs"
// What the operator reads in the window and in messages.
QString firmwareTitle(Firmware firmware); // "K3NG rotator controller"
// Empty when the firmware has an emulation of the dialect, else why not
// ("k3ng speaks easycomm2, gs232a or gs232b, not satnogs").
QString firmwareDialectConflict(Firmware firmware, Dialect dialect);

} // namespace slew::protocol
