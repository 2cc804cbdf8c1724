// SPDX-License-Identifier: GPL-3.0-or-later
#include "scheduletext.h"

#include "sky/utctime.h"

#include <QJsonArray>
#include <QObject>

namespace slew::schedule {

namespace {

QString minuteTime(double julian)
{
    return sky::utcFromJulian(julian).toString(QStringLiteral("yyyy-MM-dd HH:mm"));
}

QString isoMs(double julian)
{
    return sky::utcFromJulian(julian).toString(Qt::ISODateWithMs);
}

} // namespace

QString reasonWord(DropReason reason)
{
    switch (reason) {
    case DropReason::None: return QStringLiteral("taken");
    case DropReason::Overlap: return QStringLiteral("overlap");
    case DropReason::Unreachable: return QStringLiteral("unreachable");
    case DropReason::BelowHorizon: return QStringLiteral("below horizon");
    case DropReason::StaleElements: return QStringLiteral("stale elements");
    case DropReason::NoPlan: return QStringLiteral("no plan");
    case DropReason::NoRoomLeft: return QStringLiteral("no room left");
    }
    return QString();
}

QString describeScheduledPass(const ScheduledPass &p)
{
    const QDateTime start = sky::utcFromJulian(p.startJulian);
    const QDateTime end = sky::utcFromJulian(p.endJulian);
    QString line = QObject::tr("%1–%2 UTC  %3 [%4]  max %5°  ")
                       .arg(start.toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")),
                            end.toString(start.date() == end.date() ? QStringLiteral("HH:mm:ss")
                                                                    : QStringLiteral("yyyy-MM-dd HH:mm:ss")))
                       .arg(p.target)
                       .arg(p.priority + 1)
                       .arg(p.pass.maxElevationDeg(), 0, 'f', 1);
    if (p.taken) {
        line += QObject::tr("taken (plan worst %1°)").arg(p.predictedWorstDeg, 0, 'f', 2);
        if (p.pinned)
            line += QObject::tr(", in progress");
        if (!p.why.isEmpty())
            line += QStringLiteral(": ") + p.why;
    } else {
        line += QObject::tr("dropped: %1").arg(p.why);
    }
    return line;
}

QString describeScheduleSummary(const Schedule &s)
{
    const double end = s.settings.startJulian + s.settings.hours / 24.0;
    return QObject::tr("%1 taken, %2 dropped, %3 to %4 UTC")
        .arg(s.takenCount() == 1 ? QObject::tr("1 pass") : QObject::tr("%1 passes").arg(s.takenCount()))
        .arg(s.droppedCount())
        .arg(minuteTime(s.settings.startJulian), minuteTime(end));
}

QJsonObject scheduleToJson(const Schedule &s)
{
    QJsonArray targets;
    for (int i = 0; i < s.targets.size(); ++i)
        targets.append(QJsonObject{{QStringLiteral("priority"), i + 1}, {QStringLiteral("name"), s.targets[i]}});
    QJsonArray passes;
    for (const ScheduledPass &p : s.passes) {
        QJsonObject o{
            {QStringLiteral("target"), p.target},
            {QStringLiteral("priority"), p.priority + 1},
            {QStringLiteral("aos"), isoMs(p.pass.aos.julian)},
            {QStringLiteral("tca"), isoMs(p.pass.tca.julian)},
            {QStringLiteral("los"), isoMs(p.pass.los.julian)},
            {QStringLiteral("start"), isoMs(p.startJulian)},
            {QStringLiteral("end"), isoMs(p.endJulian)},
            {QStringLiteral("max_el_deg"), p.pass.maxElevationDeg()},
            {QStringLiteral("aos_az_deg"), p.pass.aos.azimuthDeg},
            {QStringLiteral("los_az_deg"), p.pass.los.azimuthDeg},
            {QStringLiteral("taken"), p.taken},
            {QStringLiteral("reason"), reasonWord(p.reason)},
        };
        o.insert(QStringLiteral("norad"), p.norad != 0 ? QJsonValue(p.norad) : QJsonValue());
        if (!p.why.isEmpty())
            o.insert(QStringLiteral("why"), p.why);
        if (p.plan.isValid())
            o.insert(QStringLiteral("planned_worst_deg"), p.predictedWorstDeg);
        if (p.pinned)
            o.insert(QStringLiteral("in_progress"), true);
        passes.append(o);
    }
    QJsonArray notes;
    for (const QString &n : s.notes)
        notes.append(n);
    return QJsonObject{
        {QStringLiteral("start"), isoMs(s.settings.startJulian)},
        {QStringLiteral("end"), isoMs(s.settings.startJulian + s.settings.hours / 24.0)},
        {QStringLiteral("min_el_deg"), s.settings.minElevationDeg},
        {QStringLiteral("guard_s"), s.settings.guardSeconds},
        {QStringLiteral("targets"), targets},
        {QStringLiteral("passes"), passes},
        {QStringLiteral("taken"), s.takenCount()},
        {QStringLiteral("dropped"), s.droppedCount()},
        {QStringLiteral("notes"), notes},
    };
}

} // namespace slew::schedule
