// SPDX-License-Identifier: GPL-3.0-or-later
#include "tracking/passplanbadge.h"

#include <QObject>
#include <QStringList>

namespace slew::ui {

QString passPlanBadge(const tracking::PassPlan &plan)
{
    if (!plan.isValid())
        return QObject::tr("no plan: %1").arg(plan.refusal);
    QStringList parts;
    if (plan.overTheTop)
        parts << QObject::tr("over the top");
    else if (plan.flipped)
        parts << QObject::tr("flip");
    if (plan.usesOverlap)
        parts << QObject::tr("overlap");
    if (plan.unwinds > 0)
        parts << QObject::tr("unwind");
    if (!plan.followable())
        parts << QObject::tr("lags %1°").arg(plan.predictedWorstDeg, 0, 'f', 1);
    return parts.isEmpty() ? QObject::tr("plain") : parts.join(QStringLiteral(", "));
}

} // namespace slew::ui
