// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The picture of a recorded pass, for `slew --pass-report` and the
// window's History page: a title, the sky plot (passskyplot.h) beside the
// pass's figures, and the pointing error against time (passerrorchart.h)
// across the foot. Drawn with QPainter on an image in the window's colours:
// no widget, no display.

#include "records/passrecord.h"

#include <QImage>
#include <QList>
#include <QStringList>

namespace slew::ui {

inline constexpr int kPassReportWidth = 1200;
inline constexpr int kPassReportHeight = 900;

QImage renderPassReport(const records::PassRecord &record, const QList<records::PassSample> &samples,
                        QSize size = QSize(kPassReportWidth, kPassReportHeight));

// The figures as the picture lists them, a label and a value a line:
// "Pointing RMS", "0.307°". Values the record lacks read "—".
QList<std::pair<QString, QString>> passFigureLines(const records::PassRecord &record);

// "2018-01-22 09:17:51 UTC"; "—" for no time.
QString passTimeText(const QDateTime &utc);

} // namespace slew::ui
