// SPDX-License-Identifier: GPL-3.0-or-later
#include "remotecommand.h"

#include "jsonfields.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <array>

namespace slew::remote {
namespace {

struct KindName {
    RemoteCommand::Kind kind;
    const char *name;
};

constexpr std::array<KindName, 12> kKinds{{
    {RemoteCommand::Kind::Goto, "goto"},
    {RemoteCommand::Kind::Stop, "stop"},
    {RemoteCommand::Kind::Park, "park"},
    {RemoteCommand::Kind::Home, "home"},
    {RemoteCommand::Kind::Track, "track"},
    {RemoteCommand::Kind::Untrack, "untrack"},
    {RemoteCommand::Kind::Jog, "jog"},
    {RemoteCommand::Kind::Schedule, "schedule"},
    {RemoteCommand::Kind::SchedulePreview, "schedule_preview"},
    {RemoteCommand::Kind::Unschedule, "unschedule"},
    {RemoteCommand::Kind::RadioHold, "radio_hold"},
    {RemoteCommand::Kind::ClearFault, "clear_fault"},
}};

// "goto, stop, … or radio_hold", for a command of no known kind.
QString everyKind()
{
    QStringList names;
    for (const KindName &k : kKinds)
        names << QLatin1String(k.name);
    const QString last = names.takeLast();
    return QStringLiteral("%1 or %2").arg(names.join(QStringLiteral(", ")), last);
}

// A position the gate then judges: any finite angle within a turn or two,
// so the gate's own words say what is out of the rotator's travel.
constexpr input::NumberRange kAngle{-10000, 10000, "°"};

} // namespace

QString commandName(RemoteCommand::Kind kind)
{
    for (const KindName &k : kKinds) {
        if (k.kind == kind)
            return QLatin1String(k.name);
    }
    return {};
}

ParsedCommand parseRemoteCommand(const QByteArray &payload)
{
    ParsedCommand out;
    QString why;
    auto parsed = JsonFields::parse(payload, kLargestCommand, &why);
    if (!parsed) {
        out.error = QStringLiteral("the command is %1").arg(why);
        return out;
    }
    JsonFields &f = *parsed;
    // The id first, so that even a refusal can be answered.
    if (f.has(QStringLiteral("id"))) {
        const QJsonValue id = QJsonDocument::fromJson(payload).object().value(QStringLiteral("id"));
        if (id.isDouble()) {
            if (const auto n = f.whole(QStringLiteral("id"), 0, 999999999999LL))
                out.id = QString::number(*n);
        } else if (const auto text = f.text(QStringLiteral("id"), kLongestCommandId)) {
            out.id = *text;
        }
        if (!f.ok()) {
            out.error = f.error();
            out.id.clear();
            return out;
        }
    }
    RemoteCommand c;
    c.id = out.id;
    const auto name = f.text(QStringLiteral("cmd"), 16, true);
    if (!name) {
        out.error = f.error();
        return out;
    }
    bool known = false;
    for (const KindName &k : kKinds) {
        if (*name == QLatin1String(k.name)) {
            c.kind = k.kind;
            known = true;
        }
    }
    if (!known) {
        out.error = QStringLiteral("unknown command '%1': %2").arg(*name, everyKind());
        return out;
    }
    switch (c.kind) {
    case RemoteCommand::Kind::Goto:
        c.azimuth = f.number(QStringLiteral("az"), kAngle, true).value_or(0);
        c.elevation = f.number(QStringLiteral("el"), kAngle, true).value_or(0);
        break;
    case RemoteCommand::Kind::Jog:
        c.azSpeed = f.number(QStringLiteral("az_speed"), {-kFastestJog, kFastestJog, "°/s"}).value_or(0);
        c.elSpeed = f.number(QStringLiteral("el_speed"), {-kFastestJog, kFastestJog, "°/s"}).value_or(0);
        c.leaseMs = int(f.whole(QStringLiteral("lease_ms"), kShortestJogLeaseMs, kLongestJogLeaseMs)
                            .value_or(kLongestJogLeaseMs));
        if (f.ok() && !f.has(QStringLiteral("az_speed")) && !f.has(QStringLiteral("el_speed")))
            f.fail(QStringLiteral("a jog names az_speed, el_speed or both"));
        break;
    case RemoteCommand::Kind::Track:
        if (const auto target = f.text(QStringLiteral("target"), kLongestTrackTarget, true)) {
            c.target = target->trimmed();
            if (c.target.isEmpty())
                f.fail(QStringLiteral("'target' is empty"));
        }
        c.minElevation = f.number(QStringLiteral("min_el"), {-5, 90, "°"});
        break;
    case RemoteCommand::Kind::Schedule:
    case RemoteCommand::Kind::SchedulePreview: {
        // A preview is asked for its answer.
        if (c.kind == RemoteCommand::Kind::SchedulePreview && c.id.isEmpty())
            f.fail(QStringLiteral("a schedule_preview needs an 'id' to be answered by"));
        // An empty list is the station's to refuse, in the words every face hears.
        const auto targets = f.texts(QStringLiteral("targets"), kMostScheduleTargets, kLongestTrackTarget, true);
        for (qsizetype i = 0; targets && i < targets->size(); ++i) {
            c.targets << targets->at(i).trimmed();
            if (c.targets.last().isEmpty())
                f.fail(QStringLiteral("'targets' item %1 is empty").arg(i + 1));
        }
        const face::ScheduleRequest defaults;
        c.schedule.hours = f.number(QStringLiteral("hours"), face::kScheduleHours).value_or(defaults.hours);
        c.schedule.minElevationDeg =
            f.number(QStringLiteral("min_el"), face::kScheduleMinElevation).value_or(defaults.minElevationDeg);
        c.schedule.guardSeconds = f.number(QStringLiteral("guard_s"), face::kScheduleGuard).value_or(defaults.guardSeconds);
        break;
    }
    case RemoteCommand::Kind::RadioHold:
        c.held = f.flag(QStringLiteral("held"), true).value_or(false);
        break;
    default:
        break;
    }
    if (!f.noOthers()) {
        out.error = f.error();
        return out;
    }
    out.command = c;
    return out;
}

QByteArray encodeRemoteCommand(const RemoteCommand &c)
{
    QJsonObject o;
    if (!c.id.isEmpty())
        o.insert(QStringLiteral("id"), c.id);
    o.insert(QStringLiteral("cmd"), commandName(c.kind));
    switch (c.kind) {
    case RemoteCommand::Kind::Goto:
        o.insert(QStringLiteral("az"), c.azimuth);
        o.insert(QStringLiteral("el"), c.elevation);
        break;
    case RemoteCommand::Kind::Jog:
        o.insert(QStringLiteral("az_speed"), c.azSpeed);
        o.insert(QStringLiteral("el_speed"), c.elSpeed);
        o.insert(QStringLiteral("lease_ms"), c.leaseMs);
        break;
    case RemoteCommand::Kind::Track:
        o.insert(QStringLiteral("target"), c.target);
        if (c.minElevation)
            o.insert(QStringLiteral("min_el"), *c.minElevation);
        break;
    case RemoteCommand::Kind::Schedule:
    case RemoteCommand::Kind::SchedulePreview:
        o.insert(QStringLiteral("targets"), QJsonArray::fromStringList(c.targets));
        o.insert(QStringLiteral("hours"), c.schedule.hours);
        o.insert(QStringLiteral("min_el"), c.schedule.minElevationDeg);
        o.insert(QStringLiteral("guard_s"), c.schedule.guardSeconds);
        break;
    case RemoteCommand::Kind::RadioHold:
        o.insert(QStringLiteral("held"), c.held);
        break;
    default:
        break;
    }
    return QJsonDocument(o).toJson(QJsonDocument::Compact);
}

QByteArray encodeRemoteReply(const RemoteReply &r)
{
    QJsonObject o;
    o.insert(QStringLiteral("id"), r.id);
    o.insert(QStringLiteral("ok"), r.ok);
    if (!r.ok)
        o.insert(QStringLiteral("error"), r.error.left(kLongestReplyError));
    if (r.ok && r.preview)
        o.insert(QStringLiteral("preview"), schedulePreviewObject(*r.preview));
    return QJsonDocument(o).toJson(QJsonDocument::Compact);
}

std::optional<RemoteReply> parseRemoteReply(const QByteArray &payload, QString *error)
{
    auto parsed = JsonFields::parse(payload, kLargestReply, error);
    if (!parsed)
        return std::nullopt;
    JsonFields &f = *parsed;
    RemoteReply r;
    r.id = f.text(QStringLiteral("id"), kLongestCommandId, true).value_or(QString());
    r.ok = f.flag(QStringLiteral("ok"), true).value_or(false);
    r.error = f.text(QStringLiteral("error"), kLongestReplyError, !r.ok && f.ok()).value_or(QString());
    if (f.ok() && !r.ok && r.error.trimmed().isEmpty())
        f.fail(QStringLiteral("a refusal without its reason ('error' is empty)"));
    if (const auto preview = f.object(QStringLiteral("preview")); preview && f.ok()) {
        QString why;
        r.preview = readSchedulePreview(*preview, &why);
        if (!r.preview)
            f.fail(QStringLiteral("'preview': %1").arg(why));
        else if (!r.ok)
            f.fail(QStringLiteral("a refusal with a preview"));
    }
    if (!f.noOthers()) {
        *error = f.error();
        return std::nullopt;
    }
    return r;
}

} // namespace slew::remote
