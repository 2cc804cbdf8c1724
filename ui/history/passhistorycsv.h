// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The History page's passes as a spreadsheet wants them, in the telemetry
// export's conventions (telemetrycsv.h): one row per pass, a header of
// names with ASCII units ("Max el (deg)", "Doppler RMS (Hz)"), times as
// ISO 8601 UTC with milliseconds, fields quoted as RFC 4180 has it, and
// an empty cell where the record has no value. Pure: no widgets in here.

#include "records/passrecord.h"

#include <QByteArray>
#include <QList>

class QIODevice;

namespace slew::ui {

// The header row and a row per pass; false when the device would not take it.
bool writePassHistoryCsv(QIODevice &out, const QList<records::PassRecord> &passes);

// One field, quoted when it holds a comma, a quote or a line break.
QByteArray csvField(const QString &text);

} // namespace slew::ui
