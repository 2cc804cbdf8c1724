// SPDX-License-Identifier: GPL-3.0-or-later
#include "history/passreportpicture.h"

#include "history/passerrorchart.h"
#include "history/passskyplot.h"

#include <QObject>
#include <QPainter>

namespace slew::ui {
namespace {

const QColor kBackground(0x14, 0x17, 0x1c);
const QColor kText(0xdc, 0xe2, 0xea);
const QColor kLabel(0x9a, 0xa5, 0xb4);
const QColor kTracked(0x4c, 0xd9, 0x64);
const QColor kInterrupted(0xf2, 0x9a, 0x3c);
const QColor kDropped(0xe5, 0x48, 0x48);

const QString kNone = QStringLiteral("—");

QString degrees(const std::optional<double> &value, int decimals)
{
    return value ? QStringLiteral("%1°").arg(*value, 0, 'f', decimals) : kNone;
}

QString hertz(const std::optional<double> &value)
{
    return value ? QStringLiteral("%1 Hz").arg(*value, 0, 'f', 1) : kNone;
}

QColor outcomeColour(records::Outcome outcome)
{
    switch (outcome) {
    case records::Outcome::Tracked: return kTracked;
    case records::Outcome::Dropped: return kDropped;
    default: return kInterrupted;
    }
}

QFont pixelFont(const QFont &base, int pixels, bool bold = false)
{
    QFont f = base;
    f.setPixelSize(pixels);
    f.setBold(bold);
    return f;
}

} // namespace

QString passTimeText(const QDateTime &utc)
{
    return utc.isValid() ? utc.toUTC().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")) + QStringLiteral(" UTC") : kNone;
}

QList<std::pair<QString, QString>> passFigureLines(const records::PassRecord &r)
{
    QList<std::pair<QString, QString>> lines{
        {QObject::tr("Target"), r.planned.target},
        {QObject::tr("NORAD"), r.planned.norad ? QString::number(*r.planned.norad) : kNone},
        {QObject::tr("AOS"), passTimeText(r.planned.aos)},
        {QObject::tr("TCA"), passTimeText(r.planned.tca)},
        {QObject::tr("LOS"), passTimeText(r.planned.los)},
        {QObject::tr("Max elevation"), degrees(r.planned.maxElevationDeg, 1)},
        {QObject::tr("Planned worst"), degrees(r.planned.plannedWorstDeg, 2)},
        {QObject::tr("Pointing RMS"), degrees(r.figures.rmsDeg, 3)},
        {QObject::tr("Pointing worst"), degrees(r.figures.worstDeg, 2)},
        {QObject::tr("Commands"), r.figures.commands ? QString::number(*r.figures.commands) : kNone},
    };
    if (r.figures.dopplerRmsHz || r.figures.dopplerWorstHz) {
        lines.append({QObject::tr("Doppler RMS"), hertz(r.figures.dopplerRmsHz)});
        lines.append({QObject::tr("Doppler worst"), hertz(r.figures.dopplerWorstHz)});
    }
    lines.append({QObject::tr("Outcome"), records::outcomeName(r.outcome)});
    if (!r.reason.isEmpty())
        lines.append({QObject::tr("Why"), r.reason});
    lines.append({QObject::tr("Samples"), QString::number(r.samples)});
    return lines;
}

QImage renderPassReport(const records::PassRecord &record, const QList<records::PassSample> &samples, QSize size)
{
    QImage image(size, QImage::Format_RGB32);
    image.fill(kBackground);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    p.setRenderHint(QPainter::TextAntialiasing);
    const QFont base = p.font();
    const double w = size.width(), h = size.height();

    // Title: what, which pass, when.
    p.setFont(pixelFont(base, 22, true));
    p.setPen(kText);
    const QString title = record.planned.norad
                              ? QObject::tr("%1 (NORAD %2)").arg(record.planned.target).arg(*record.planned.norad)
                              : record.planned.target;
    p.drawText(QRectF(20, 12, w - 40, 30), Qt::AlignLeft | Qt::AlignVCenter,
               p.fontMetrics().elidedText(title, Qt::ElideRight, int(w * 0.6)));
    p.setFont(pixelFont(base, 15));
    p.setPen(kLabel);
    p.drawText(QRectF(20, 12, w - 40, 30), Qt::AlignRight | Qt::AlignVCenter,
               QObject::tr("pass %1 · %2%3")
                   .arg(record.id)
                   .arg(passTimeText(record.planned.aos))
                   .arg(record.planned.rehearsal ? QObject::tr(" · rehearsal") : QString()));

    // The sky, left; the figures, right; the error across the foot.
    const double top = 52, skySide = std::min(w * 0.5, h * 0.62);
    p.setFont(pixelFont(base, 13));
    paintPassSky(p, QRectF(12, top, skySide, skySide), samples, record);

    const QRectF figures(skySide + 40, top + 10, w - skySide - 60, skySide - 20);
    double y = figures.top();
    const double labelWidth = 150, lineHeight = 24;
    for (const auto &[label, value] : passFigureLines(record)) {
        p.setFont(pixelFont(base, 15));
        p.setPen(kLabel);
        p.drawText(QRectF(figures.left(), y, labelWidth, lineHeight), Qt::AlignLeft | Qt::AlignVCenter, label);
        const bool outcome = label == QObject::tr("Outcome");
        p.setFont(pixelFont(base, 15, outcome));
        p.setPen(outcome ? outcomeColour(record.outcome) : kText);
        // A long reason wraps over the lines it needs.
        const QRectF valueBox(figures.left() + labelWidth, y, figures.width() - labelWidth, figures.bottom() - y);
        const QRectF used = p.boundingRect(valueBox, Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap, value);
        p.drawText(QRectF(valueBox.left(), y + (lineHeight - p.fontMetrics().height()) / 2, valueBox.width(),
                          valueBox.height()),
                   Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap, value);
        y += std::max(lineHeight, used.height() + 6);
    }

    p.setFont(pixelFont(base, 13));
    paintPassError(p, QRectF(12, top + skySide + 8, w - 24, h - top - skySide - 16), samples, record);
    p.end();
    return image;
}

} // namespace slew::ui
