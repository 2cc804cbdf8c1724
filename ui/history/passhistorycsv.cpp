// SPDX-License-Identifier: GPL-3.0-or-later
#include "history/passhistorycsv.h"

#include <QIODevice>

namespace slew::ui {
namespace {

// Rounded to `decimals` places without trailing zeros: 0.25, not 0.250.
QString rounded(const std::optional<double> &value, int decimals)
{
    if (!value)
        return {};
    QString text = QString::number(*value, 'f', decimals);
    if (text.contains(u'.')) {
        while (text.endsWith(u'0'))
            text.chop(1);
        if (text.endsWith(u'.'))
            text.chop(1);
    }
    return text == QLatin1String("-0") ? QStringLiteral("0") : text;
}

QString time(const QDateTime &utc)
{
    return records::storedTime(utc);
}

} // namespace

QByteArray csvField(const QString &text)
{
    QByteArray bytes = text.toUtf8();
    if (!bytes.contains(',') && !bytes.contains('"') && !bytes.contains('\n') && !bytes.contains('\r'))
        return bytes;
    bytes.replace('"', "\"\"");
    return '"' + bytes + '"';
}

bool writePassHistoryCsv(QIODevice &out, const QList<records::PassRecord> &passes)
{
    const QByteArray header =
        "id,target,norad,aos_utc,tca_utc,los_utc,Max el (deg),Planned worst (deg),Pointing RMS (deg),"
        "Pointing worst (deg),commands,Doppler RMS (Hz),Doppler worst (Hz),outcome,reason,rehearsal,samples\n";
    bool ok = out.write(header) >= 0;
    for (const records::PassRecord &r : passes) {
        const QStringList cells{
            QString::number(r.id),
            r.planned.target,
            r.planned.norad ? QString::number(*r.planned.norad) : QString(),
            time(r.planned.aos),
            time(r.planned.tca),
            time(r.planned.los),
            rounded(r.planned.maxElevationDeg, 1),
            rounded(r.planned.plannedWorstDeg, 3),
            rounded(r.figures.rmsDeg, 3),
            rounded(r.figures.worstDeg, 3),
            r.figures.commands ? QString::number(*r.figures.commands) : QString(),
            rounded(r.figures.dopplerRmsHz, 1),
            rounded(r.figures.dopplerWorstHz, 1),
            records::outcomeName(r.outcome),
            r.reason,
            r.planned.rehearsal ? QStringLiteral("yes") : QStringLiteral("no"),
            QString::number(r.samples),
        };
        QByteArray row;
        for (const QString &cell : cells)
            row += (row.isEmpty() ? QByteArray() : QByteArray(",")) + csvField(cell);
        ok = ok && out.write(row + '\n') >= 0;
    }
    return ok;
}

} // namespace slew::ui
