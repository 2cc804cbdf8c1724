// SPDX-License-Identifier: GPL-3.0-or-later
#include "elementage.h"

#include "utctime.h"

#include <QObject>

#include <cmath>

namespace slew::sky {

double elementAgeDays(const ElementSet &set, double julian)
{
    return std::abs(julian - set.epochJulian());
}

QString elementsTooOld(const ElementSet &set, double julian, double limitDays, const QString &when)
{
    const double age = elementAgeDays(set, julian);
    if (age <= limitDays)
        return {};
    return QObject::tr("its elements are %1 days from %2 (epoch %3); the limit is %4 days")
        .arg(age, 0, 'f', 1)
        .arg(when, isoUtc(set.epochJulian()))
        .arg(limitDays, 0, 'g', 4);
}

QList<ElementAge> staleElements(const QList<ElementSet> &sets, double julian, double limitDays)
{
    QList<ElementAge> stale;
    for (const ElementSet &t : sets)
        if (const double age = elementAgeDays(t, julian); age > limitDays)
            stale.append({&t, age});
    return stale;
}

} // namespace slew::sky
