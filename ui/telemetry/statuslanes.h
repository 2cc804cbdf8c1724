// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the status lanes of the telemetry charts show: the controller's
// status and error registers (GS per axis, GE; docs/protocol.md) as named
// states over time rather than as the numbers they are on the wire. A
// register is recorded only when it changes, so each value holds from its
// sample to the next: a lane is a row of such stretches, each coloured by
// the state that matters most in it and labelled with the names the session
// gives the bits. Pure: no widgets in here.

#include "model/telemetryhistory.h"

#include <QColor>
#include <QString>

#include <vector>

class QFontMetricsF;

namespace slew::ui {

// Which register a lane shows: one axis' byte of GS, or GE.
enum class StatusRegister { AxisStatus, ErrorFlags };

// The colour a stretch is drawn in, from the bit that matters most.
enum class StatusTone { None, Idle, Moving, Pointing, Error };

// One value of a register, in force from fromMs until toMs.
struct StatusStretch {
    qint64 fromMs = 0;
    qint64 toMs = 0;
    int bits = 0;
};

// The stretches of series `id` that lie in [fromMs, toMs], clipped to it,
// for a lane `columns` pixels wide. The value in force when the window
// opens is the last one recorded before it. A register that flaps is read
// as the history reduces any series, the lowest and highest value in each
// pixel column, and changes closer together than a column make one stretch
// holding every bit set in any of them: a stretch costs a pixel at most,
// and a moment's error still shows (the error bit is each register's
// highest, so the highest value in a column has it if any value there did).
std::vector<StatusStretch> statusStretches(const model::TelemetryHistory &history, int id, qint64 fromMs,
                                           qint64 toMs, int columns);

StatusTone toneOf(StatusRegister reg, int bits);
// The names of the bits that are set: "moving, pointing", "motor error",
// "no error" (GE's 1, or nothing set).
QString stateName(StatusRegister reg, int bits);
// The state's name cut to `width` at a whole name, never inside one:
// "moving, …" for "moving, pointing"; empty when not even the first name
// fits. "no error" cut to "no …" read as the opposite of what it says.
QString fittedStateName(const QString &name, const QFontMetricsF &metrics, double width);
// The register's raw value as the controller sent it: "0x06".
QString hexValue(int bits);
QColor toneColour(StatusTone tone);
// What a tone means, for the legend: "moving", "error".
QString toneName(StatusTone tone);

} // namespace slew::ui
