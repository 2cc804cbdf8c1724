// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/utctimefield.h"

#include "sky/utctime.h"

namespace slew::ui {

namespace {

const QString kFormat = QStringLiteral("yyyy-MM-dd HH:mm:ss");

} // namespace

UtcTimeField::UtcTimeField(QWidget *parent) : QLineEdit(parent)
{
    setPlaceholderText(QStringLiteral("2026-12-05 15:24:00"));
    setToolTip(tr("A UTC date and time: 2026-12-05 15:24:00, or ISO 8601 (2026-12-05T15:24:00Z)."));
    // Room for the whole instant and a little more.
    setMinimumWidth(fontMetrics().horizontalAdvance(QStringLiteral("2026-12-05 15:24:00  ")));
}

void UtcTimeField::setJulian(double julian)
{
    setText(sky::utcFromJulian(julian).toString(kFormat));
}

std::optional<double> UtcTimeField::julian(QString *why) const
{
    QString typed = text().trimmed();
    // The instant as the Time controller and the status bar show it,
    // copied with its zone.
    if (typed.endsWith(QStringLiteral("UTC"), Qt::CaseInsensitive))
        typed = typed.chopped(3).trimmed();
    const std::optional<double> julian = sky::julianFromIso(typed);
    if (!julian && why)
        *why = tr("\"%1\" is not a UTC date and time: type it as 2026-12-05 15:24:00").arg(text().trimmed());
    return julian;
}

} // namespace slew::ui
