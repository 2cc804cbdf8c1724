// SPDX-License-Identifier: GPL-3.0-or-later
#include "radio/radioplansettings.h"

#include <QSettings>

namespace slew::ui {

namespace {

constexpr char kPlansGroup[] = "radio/plans";
constexpr char kLastKey[] = "radio/lastPlan";

QString groupFor(int noradId)
{
    return QStringLiteral("%1/%2").arg(QLatin1String(kPlansGroup)).arg(noradId);
}

} // namespace

std::optional<RadioPlanTexts> keptRadioPlan(int noradId)
{
    QSettings settings;
    settings.beginGroup(groupFor(noradId));
    // The downlink is what every plan has: without it nothing was kept.
    if (!settings.contains(QStringLiteral("downlink")))
        return std::nullopt;
    RadioPlanTexts t;
    t.downlink = settings.value(QStringLiteral("downlink")).toString();
    t.uplink = settings.value(QStringLiteral("uplink")).toString();
    t.receiveMode = settings.value(QStringLiteral("receiveMode")).toString();
    t.transmitMode = settings.value(QStringLiteral("transmitMode")).toString();
    t.downlinkOffset = settings.value(QStringLiteral("downlinkOffset")).toString();
    t.uplinkOffset = settings.value(QStringLiteral("uplinkOffset")).toString();
    t.doppler = settings.value(QStringLiteral("doppler"), t.doppler).toString();
    t.uplinkFollows = settings.value(QStringLiteral("uplinkFollows"), t.uplinkFollows).toString();
    return t;
}

void keepRadioPlan(int noradId, const RadioPlanTexts &t)
{
    QSettings settings;
    settings.beginGroup(groupFor(noradId));
    settings.setValue(QStringLiteral("downlink"), t.downlink);
    settings.setValue(QStringLiteral("uplink"), t.uplink);
    settings.setValue(QStringLiteral("receiveMode"), t.receiveMode);
    settings.setValue(QStringLiteral("transmitMode"), t.transmitMode);
    settings.setValue(QStringLiteral("downlinkOffset"), t.downlinkOffset);
    settings.setValue(QStringLiteral("uplinkOffset"), t.uplinkOffset);
    settings.setValue(QStringLiteral("doppler"), t.doppler);
    settings.setValue(QStringLiteral("uplinkFollows"), t.uplinkFollows);
    settings.endGroup();
    settings.setValue(QLatin1String(kLastKey), noradId);
}

std::optional<int> lastAppliedRadioPlan()
{
    bool ok = false;
    const int norad = QSettings().value(QLatin1String(kLastKey)).toInt(&ok);
    if (!ok || norad < 0)
        return std::nullopt;
    return norad;
}

} // namespace slew::ui
