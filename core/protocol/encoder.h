// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Turning messages into wire bytes, per dialect. Pure functions: no I/O.
// The SPID dialects are binary frames, not lines (spidcodec.h). Only the
// fixed frames come from here: encodeQueryPosition gives the status frame
// and encodeStop the stop frame. A set needs the controller's resolution,
// which the session learns from its replies (spid::encodeSet); the token
// and line functions return nothing for SPID.

#include "dialect.h"
#include "message.h"

#include <QByteArray>

#include <initializer_list>

namespace slew::protocol {

// One token without separator, e.g. `AZ123.4`, `CW1,0.5`, `CR 1` (SatNOGS).
// Returns an empty array when the dialect has no such command.
QByteArray encodeToken(const Message &m, Dialect d);

// Tokens joined by single spaces and ended with `\n`, the terminator every
// Easycomm peer in docs/protocol.md accepts (GS-232: one command a line, each
// ended with `\r`; rotctld: one a line, ended with `\n`). Empty when any
// token is unsupported.
QByteArray encodeLine(std::initializer_list<Message> tokens, Dialect d);

// The commands the session sends, in each dialect's own form. rotor names
// one rotor of a multi-rotor controller (Micro-2g: 1..4); 0 addresses the
// controller's default rotor, and every other dialect ignores it.
QByteArray encodeSetPosition(double az, double el, Dialect d, int rotor = 0); // Easycomm I: full line; rotctld `P az el`; Micro-2g `Mqqq`; SPID: empty
QByteArray encodeQueryPosition(Dialect d, int rotor = 0);                     // `AZ EL\n`; empty for Easycomm I; `p`; `Cn`; SPID status frame
// How many bytes the answer to that query takes on the wire: a SPID reply's
// fixed size, or a typical position line (`AZ123.4 EL45.6\n` and the like).
int positionReplyBytes(Dialect d);
// GS-232's relative move `O+010-005`, whole degrees, each offset signed;
// empty in every other dialect.
QByteArray encodeOffset(double azimuth, double elevation, Dialect d);
QByteArray encodeStop(bool azimuth, bool elevation, Dialect d, int rotor = 0); // `SA SE\n`; rotctld `S` stops both; `Sn`; SPID stop frame (both)
// What holds the stopped axes with the drive engaged: a zero speed (`VL000
// VU000\n`), which brakes a drive that would coast. Empty for a dialect
// without speed commands.
QByteArray encodeStopHold(bool azimuth, bool elevation, Dialect d);

// Easycomm I's single line, as Hamlib model 201 writes it.
QByteArray encodeEasycomm1Line(double az, double el, quint64 up = 0, QByteArrayView upMode = "XXX",
                               quint64 down = 0, QByteArrayView downMode = "XXX");

// A controller's report of a value, for the simulator's answers: the same as
// encodeToken in Easycomm (`AZ10.0`), `+0010` / `AZ=010` in GS-232, a bare
// `10.00` (one line of a `p` answer) in rotctld.
QByteArray encodeReport(const Message &m, Dialect d);
// What goes between two reports on one answer line.
QByteArray reportSeparator(Dialect d);

// Formats a number the way the wire wants it: fixed decimals, '.' always,
// never an exponent. Used by the simulator for its replies too.
QByteArray formatNumber(double value, int decimals);

} // namespace slew::protocol
