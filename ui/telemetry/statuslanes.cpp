// SPDX-License-Identifier: GPL-3.0-or-later
#include "telemetry/statuslanes.h"

#include "session/sessiontypes.h"

#include <QCoreApplication>
#include <QFontMetricsF>
#include <QStringList>

#include <algorithm>
#include <optional>

namespace slew::ui {

std::vector<StatusStretch> statusStretches(const model::TelemetryHistory &history, int id, qint64 fromMs,
                                           qint64 toMs, int columns)
{
    columns = std::max(1, columns);
    const qint64 shortestMs = std::max<qint64>(1, (toMs - fromMs) / columns);
    std::vector<StatusStretch> out;
    int latest = 0;        // the value in force
    bool blurred = false;  // out.back() holds changes too close together to draw apart
    // A blurred stretch is one column wide; the value in force after it
    // carries on from there until `until`.
    auto carryOn = [&](qint64 until) {
        if (!blurred)
            return;
        blurred = false;
        const qint64 columnEnd = out.back().fromMs + shortestMs;
        if (until <= columnEnd)
            return;
        out.back().toMs = columnEnd;
        out.push_back({columnEnd, until, latest});
    };
    if (const std::optional<QPointF> before = history.sampleBefore(id, fromMs)) {
        latest = int(before->y());
        out.push_back({fromMs, toMs, latest});
    }
    for (const QPointF &sample : history.decimated(id, fromMs, toMs, columns)) {
        const qint64 t = qint64(sample.x());
        const int bits = int(sample.y());
        if (!out.empty() && bits == latest)
            continue; // the same value again: the stretch goes on
        if (!out.empty() && t - out.back().fromMs < shortestMs) {
            out.back().bits |= bits; // too short to draw apart: one stretch with every bit
            blurred = true;
            latest = bits;
            continue;
        }
        carryOn(t); // with the value in force until this change
        latest = bits;
        if (!out.empty())
            out.back().toMs = t;
        out.push_back({t, toMs, bits});
    }
    carryOn(toMs);
    return out;
}

StatusTone toneOf(StatusRegister reg, int bits)
{
    if (reg == StatusRegister::ErrorFlags)
        return (bits & ~session::ErrorNone) ? StatusTone::Error : StatusTone::Idle;
    if (bits & session::StatusError)
        return StatusTone::Error;
    if (bits & session::StatusMoving)
        return StatusTone::Moving;
    if (bits & session::StatusPointing)
        return StatusTone::Pointing;
    if (bits & session::StatusIdle)
        return StatusTone::Idle;
    return StatusTone::None;
}

QString stateName(StatusRegister reg, int bits)
{
    if (reg == StatusRegister::AxisStatus)
        return session::describeAxisStatus(quint8(bits));
    const QString errors = session::describeErrorFlags(bits);
    return errors.isEmpty() ? QCoreApplication::translate("StatusLanes", "no error") : errors;
}

QString fittedStateName(const QString &name, const QFontMetricsF &metrics, double width)
{
    if (metrics.horizontalAdvance(name) <= width)
        return name;
    const QString separator = QStringLiteral(", ");
    const QString more = separator + QChar(0x2026);
    QStringList names = name.split(separator);
    while (names.size() > 1) {
        names.removeLast();
        const QString cut = names.join(separator) + more;
        if (metrics.horizontalAdvance(cut) <= width)
            return cut;
    }
    return {};
}

QString hexValue(int bits)
{
    return QStringLiteral("0x%1").arg(bits, 2, 16, QLatin1Char('0'));
}

QColor toneColour(StatusTone tone)
{
    switch (tone) {
    case StatusTone::Idle: return QColor(0x5a, 0x60, 0x6e);
    case StatusTone::Moving: return QColor(0x3c, 0x8c, 0xf2);
    case StatusTone::Pointing: return QColor(0x3c, 0xb4, 0x64);
    case StatusTone::Error: return QColor(0xe5, 0x48, 0x48);
    case StatusTone::None: break;
    }
    return QColor(0x2a, 0x2c, 0x34);
}

QString toneName(StatusTone tone)
{
    switch (tone) {
    case StatusTone::Idle: return QCoreApplication::translate("StatusLanes", "idle / no error");
    case StatusTone::Moving: return QCoreApplication::translate("StatusLanes", "moving");
    case StatusTone::Pointing: return QCoreApplication::translate("StatusLanes", "pointing");
    case StatusTone::Error: return QCoreApplication::translate("StatusLanes", "error");
    case StatusTone::None: break;
    }
    return QCoreApplication::translate("StatusLanes", "none");
}

} // namespace slew::ui
