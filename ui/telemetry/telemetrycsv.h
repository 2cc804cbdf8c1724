// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The telemetry as a spreadsheet wants it: one row per time, one column
// per series headed by its name and unit, and an empty cell where a series
// has no sample at that time.
//
// Values come out as the controller sent them. The history keeps each
// sample as a float, which holds any decimal of up to six significant
// digits exactly enough to give it back: 16.04 is written as the shortest
// decimal that reads back as the stored float, "16.04", never the
// "16.040001" that eight digits of the float print. The status and error
// registers are written as their hex value and the names of their bits.
// Pure: no widgets in here.

#include "model/telemetryhistory.h"

#include <QByteArray>
#include <QString>

#include <vector>

class QIODevice;

namespace slew::ui {

struct TelemetryCsvColumn {
    enum class Kind { Number, AxisStatus, ErrorFlags };
    int series = 0;     // the history's series
    QString header;     // name and unit: "Az (deg)"
    Kind kind = Kind::Number;
    int decimals = -1;  // -1: as recorded; else rounded to this many places
};

// The columns of TelemetryRecorder's series, in its order.
std::vector<TelemetryCsvColumn> telemetryCsvColumns();

// The header row (time_utc, unix_ms, then the columns' headers) and a row
// per time in [fromMs, toMs]. False when the device would not take it.
bool writeTelemetryCsv(QIODevice &out, const model::TelemetryHistory &history,
                       const std::vector<TelemetryCsvColumn> &columns, qint64 fromMs, qint64 toMs);

// One cell: "16.04", "0x06 moving, pointing", ... (not yet quoted).
QByteArray telemetryCsvValue(const TelemetryCsvColumn &column, double value);

} // namespace slew::ui
