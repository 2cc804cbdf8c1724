// SPDX-License-Identifier: GPL-3.0-or-later
#include "stationtopics.h"

#include "brokeraddress.h"

#include <QStringList>

#include <array>

namespace slew::remote {
namespace {

struct TopicName {
    StationTopic topic;
    const char *name;
};

constexpr std::array<TopicName, 7> kTopics{{
    {StationTopic::Online, "online"},
    {StationTopic::State, "state"},
    {StationTopic::Telemetry, "telemetry"},
    {StationTopic::Command, "command"},
    {StationTopic::Reply, "reply"},
    {StationTopic::Schedule, "schedule"},
    {StationTopic::Plan, "plan"},
}};

QLatin1String nameOf(StationTopic topic)
{
    for (const TopicName &t : kTopics) {
        if (t.topic == topic)
            return QLatin1String(t.name);
    }
    return {};
}

} // namespace

QString stationTopic(const QString &stationName, StationTopic topic)
{
    return QStringLiteral("%1/%2/%3").arg(QLatin1String(kTopicRoot), stationName, nameOf(topic));
}

QString stationFilter(const QString &stationName)
{
    return QStringLiteral("%1/%2/#").arg(QLatin1String(kTopicRoot), stationName);
}

QString everyStationFilter(StationTopic topic)
{
    return QStringLiteral("%1/+/%2").arg(QLatin1String(kTopicRoot), nameOf(topic));
}

std::optional<ParsedTopic> parseStationTopic(const QString &topic)
{
    const QStringList levels = topic.split(u'/');
    if (levels.size() != 3 || levels[0] != QLatin1String(kTopicRoot) || !checkStationName(levels[1]).isEmpty())
        return std::nullopt;
    for (const TopicName &t : kTopics) {
        if (levels[2] == QLatin1String(t.name))
            return ParsedTopic{levels[1], t.topic};
    }
    return std::nullopt;
}

} // namespace slew::remote
