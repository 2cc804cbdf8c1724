// SPDX-License-Identifier: GPL-3.0-or-later
#include "stationplan.h"

#include "jsonfields.h"

#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace slew::remote {
namespace {

constexpr qint64 kLatestMs = 32503680000000LL; // the year 3000

QJsonArray pointArray(const QList<QPointF> &points)
{
    QJsonArray out;
    for (const QPointF &p : thinPoints(points, kMostPlanPoints))
        out.append(QJsonArray{std::round(p.x() * 1000) / 1000, std::round(p.y() * 1000) / 1000});
    return out;
}

} // namespace

QList<QPointF> thinPoints(const QList<QPointF> &points, int most)
{
    if (points.size() <= most || most < 2)
        return points.mid(0, std::max(most, 0));
    const qsizetype step = (points.size() - 1 + (most - 2)) / (most - 1);
    QList<QPointF> out;
    for (qsizetype i = 0; i < points.size() - 1; i += step)
        out.append(points.at(i));
    out.append(points.last());
    return out;
}

QByteArray encodeStationPlan(const face::StationPlan &p)
{
    QJsonObject o;
    o.insert(QStringLiteral("unix_ms"), double(p.unixMs));
    if (!p.target.isEmpty()) {
        o.insert(QStringLiteral("target"), p.target);
        if (p.norad > 0)
            o.insert(QStringLiteral("norad"), p.norad);
        if (p.aosMs)
            o.insert(QStringLiteral("aos_ms"), double(*p.aosMs));
        if (p.tcaMs)
            o.insert(QStringLiteral("tca_ms"), double(*p.tcaMs));
        if (p.losMs)
            o.insert(QStringLiteral("los_ms"), double(*p.losMs));
        if (p.maxElevation)
            o.insert(QStringLiteral("max_el"), *p.maxElevation);
        if (p.plannedWorstDeg)
            o.insert(QStringLiteral("planned_worst_deg"), *p.plannedWorstDeg);
        o.insert(QStringLiteral("flipped"), p.flipped);
        o.insert(QStringLiteral("over_the_top"), p.overTheTop);
        o.insert(QStringLiteral("unwinds"), p.unwinds);
        o.insert(QStringLiteral("az_turn_start"), p.azimuthTurnStart);
        o.insert(QStringLiteral("az_turn_end"), p.azimuthTurnEnd);
        o.insert(QStringLiteral("sky"), pointArray(p.sky));
        o.insert(QStringLiteral("path"), pointArray(p.path));
    }
    return QJsonDocument(o).toJson(QJsonDocument::Compact);
}

std::optional<face::StationPlan> parseStationPlan(const QByteArray &payload, QString *error)
{
    std::optional<JsonFields> f = JsonFields::parse(payload, kLargestPlanMessage, error);
    if (!f)
        return std::nullopt;
    face::StationPlan p;
    p.unixMs = f->whole(QStringLiteral("unix_ms"), 0, kLatestMs, true).value_or(0);
    p.target = f->text(QStringLiteral("target"), 100).value_or(QString());
    if (f->has(QStringLiteral("target")) && p.target.isEmpty())
        f->fail(QStringLiteral("'target' is empty"));
    p.norad = int(f->whole(QStringLiteral("norad"), 1, 999999999).value_or(0));
    p.aosMs = f->whole(QStringLiteral("aos_ms"), 0, kLatestMs);
    p.tcaMs = f->whole(QStringLiteral("tca_ms"), 0, kLatestMs);
    p.losMs = f->whole(QStringLiteral("los_ms"), 0, kLatestMs);
    if (p.aosMs && p.losMs && *p.losMs < *p.aosMs)
        f->fail(QStringLiteral("'los_ms' comes before 'aos_ms'"));
    p.maxElevation = f->number(QStringLiteral("max_el"), {-90, 90, "°"});
    p.plannedWorstDeg = f->number(QStringLiteral("planned_worst_deg"), {0, 360, "°"});
    p.flipped = f->flag(QStringLiteral("flipped")).value_or(false);
    p.overTheTop = f->flag(QStringLiteral("over_the_top")).value_or(false);
    p.unwinds = int(f->whole(QStringLiteral("unwinds"), 0, 100).value_or(0));
    p.azimuthTurnStart = f->number(QStringLiteral("az_turn_start"), {-360, 360, "°"}).value_or(0);
    p.azimuthTurnEnd = f->number(QStringLiteral("az_turn_end"), {0, 720, "°"}).value_or(360);
    p.sky = f->points(QStringLiteral("sky"), kMostPlanPoints).value_or(QList<QPointF>());
    p.path = f->points(QStringLiteral("path"), kMostPlanPoints).value_or(QList<QPointF>());
    if (p.target.isEmpty() && (!p.sky.isEmpty() || !p.path.isEmpty()))
        f->fail(QStringLiteral("a path without a 'target'"));
    if (!f->noOthers() || !f->ok()) {
        *error = f->error();
        return std::nullopt;
    }
    return p;
}

} // namespace slew::remote
