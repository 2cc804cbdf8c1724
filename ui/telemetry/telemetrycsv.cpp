// SPDX-License-Identifier: GPL-3.0-or-later
#include "telemetry/telemetrycsv.h"

#include "telemetry/statuslanes.h"
#include "telemetry/telemetryrecorder.h"

#include "sky/utctime.h"

#include <QDateTime>
#include <QIODevice>

#include <charconv>
#include <cmath>

namespace slew::ui {

namespace {

using Series = TelemetryRecorder::Series;
using Kind = TelemetryCsvColumn::Kind;

// Units in ASCII: a spreadsheet that guesses the file's encoding turns
// "°" into "Â°".
QString unitOf(Series s)
{
    switch (s) {
    case Series::AzActual:
    case Series::ElActual:
    case Series::AzCommanded:
    case Series::ElCommanded:
    case Series::PointingError: return QStringLiteral("deg");
    case Series::AzVelocity:
    case Series::ElVelocity: return QStringLiteral("deg/s");
    case Series::Temperature: return QStringLiteral("degC");
    case Series::ReceiveDopplerError:
    case Series::TransmitDopplerError: return QStringLiteral("Hz");
    default: return {}; // load is the controller's own number; the registers are bits
    }
}

// A field as RFC 4180 has it: quoted when it holds a comma, a quote or a
// line break, with its quotes doubled.
QByteArray field(const QByteArray &text)
{
    if (!text.contains(',') && !text.contains('"') && !text.contains('\n') && !text.contains('\r'))
        return text;
    QByteArray quoted = text;
    quoted.replace('"', "\"\"");
    return '"' + quoted + '"';
}

// The shortest decimal that reads back as the same float: what the
// controller sent, for any value of up to six significant digits.
QByteArray shortestDecimal(float value)
{
    char buffer[64];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed);
    if (ec != std::errc())
        return QByteArray::number(double(value), 'g', 9);
    return QByteArray(buffer, int(end - buffer));
}

// Rounded to `decimals` places, without trailing zeros: 0.25, not 0.250.
QByteArray rounded(double value, int decimals)
{
    QByteArray text = QByteArray::number(value, 'f', decimals);
    if (text.contains('.')) {
        while (text.endsWith('0'))
            text.chop(1);
        if (text.endsWith('.'))
            text.chop(1);
    }
    return text;
}

} // namespace

std::vector<TelemetryCsvColumn> telemetryCsvColumns()
{
    std::vector<TelemetryCsvColumn> columns;
    for (int s = 0; s < TelemetryRecorder::SeriesCount; ++s) {
        const auto series = Series(s);
        TelemetryCsvColumn c;
        c.series = s;
        const QString unit = unitOf(series);
        c.header = unit.isEmpty() ? TelemetryRecorder::seriesLabel(series)
                                  : QStringLiteral("%1 (%2)").arg(TelemetryRecorder::seriesLabel(series), unit);
        if (series == Series::AzStatus || series == Series::ElStatus)
            c.kind = Kind::AxisStatus;
        else if (series == Series::ErrorFlags)
            c.kind = Kind::ErrorFlags;
        // Slew works the pointing error out itself: a thousandth of a degree
        // is finer than any rotator points.
        if (series == Series::PointingError)
            c.decimals = 3;
        // The radio's error, measured against a frequency to the hertz:
        // a tenth is all there is to it.
        if (series == Series::ReceiveDopplerError || series == Series::TransmitDopplerError)
            c.decimals = 1;
        columns.push_back(c);
    }
    return columns;
}

QByteArray telemetryCsvValue(const TelemetryCsvColumn &column, double value)
{
    if (!std::isfinite(value))
        return {};
    switch (column.kind) {
    case Kind::AxisStatus:
    case Kind::ErrorFlags: {
        const int bits = int(value);
        const StatusRegister reg = column.kind == Kind::AxisStatus ? StatusRegister::AxisStatus
                                                                    : StatusRegister::ErrorFlags;
        return (hexValue(bits) + QLatin1Char(' ') + stateName(reg, bits)).toUtf8();
    }
    case Kind::Number: break;
    }
    QByteArray text = column.decimals < 0 ? shortestDecimal(float(value)) : rounded(value, column.decimals);
    if (text == "-0")
        text = "0";
    return text;
}

bool writeTelemetryCsv(QIODevice &out, const model::TelemetryHistory &history,
                       const std::vector<TelemetryCsvColumn> &columns, qint64 fromMs, qint64 toMs)
{
    QByteArray header = "time_utc,unix_ms";
    std::vector<int> ids;
    for (const TelemetryCsvColumn &c : columns) {
        header += ',' + field(c.header.toUtf8());
        ids.push_back(c.series);
    }
    bool ok = out.write(header + '\n') >= 0;
    history.forEachRow(ids, fromMs, toMs, [&](qint64 t, const std::vector<double> &values) {
        QByteArray row = sky::utcFromUnixMs(t).toString(Qt::ISODateWithMs).toLatin1() + ','
            + QByteArray::number(t);
        for (std::size_t i = 0; i < columns.size(); ++i)
            row += ',' + field(telemetryCsvValue(columns[i], values[i]));
        ok = ok && out.write(row + '\n') >= 0;
    });
    return ok;
}

} // namespace slew::ui
