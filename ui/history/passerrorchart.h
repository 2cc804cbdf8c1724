// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A recorded pass's pointing error against time: degrees on the sky
// against minutes from AOS, with AOS, TCA and LOS marked by vertical lines
// and the planner's predicted worst as a dashed level.

#include "records/passrecord.h"

#include <QList>
#include <QRectF>

class QPainter;

namespace slew::ui {

void paintPassError(QPainter &p, const QRectF &area, const QList<records::PassSample> &samples,
                    const records::PassRecord &record);

// A step of 1, 2 or 5 times a power of ten that cuts `span` into at most
// `maxSteps` pieces.
double niceStep(double span, int maxSteps);

} // namespace slew::ui
