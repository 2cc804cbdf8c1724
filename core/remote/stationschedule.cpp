// SPDX-License-Identifier: GPL-3.0-or-later
#include "stationschedule.h"

#include "jsonfields.h"

#include "schedule/scheduletext.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>

namespace slew::remote {
namespace {

constexpr qint64 kLatestMs = 32503680000000LL; // the year 3000
constexpr input::NumberRange kAzimuth{0, 360, "°"};

qint64 unixMs(double julian)
{
    return qint64(std::llround((julian - 2440587.5) * 86400000.0));
}

double julianOf(qint64 ms)
{
    return 2440587.5 + double(ms) / 86400000.0;
}

const schedule::DropReason kReasons[] = {
    schedule::DropReason::None,          schedule::DropReason::Overlap,       schedule::DropReason::Unreachable,
    schedule::DropReason::BelowHorizon,  schedule::DropReason::StaleElements, schedule::DropReason::NoPlan,
    schedule::DropReason::NoRoomLeft,
};

std::optional<schedule::DropReason> reasonNamed(const QString &word)
{
    for (const schedule::DropReason r : kReasons) {
        if (schedule::reasonWord(r) == word)
            return r;
    }
    return std::nullopt;
}

QJsonObject passObject(const schedule::ScheduledPass &p)
{
    QJsonObject o{
        {QStringLiteral("target"), p.target},
        {QStringLiteral("priority"), p.priority + 1},
        {QStringLiteral("aos_ms"), double(unixMs(p.pass.aos.julian))},
        {QStringLiteral("tca_ms"), double(unixMs(p.pass.tca.julian))},
        {QStringLiteral("los_ms"), double(unixMs(p.pass.los.julian))},
        {QStringLiteral("start_ms"), double(unixMs(p.startJulian))},
        {QStringLiteral("end_ms"), double(unixMs(p.endJulian))},
        {QStringLiteral("max_el"), p.pass.maxElevationDeg()},
        {QStringLiteral("aos_az"), p.pass.aos.azimuthDeg},
        {QStringLiteral("los_az"), p.pass.los.azimuthDeg},
        {QStringLiteral("taken"), p.taken},
        {QStringLiteral("reason"), schedule::reasonWord(p.reason)},
    };
    if (p.norad > 0)
        o.insert(QStringLiteral("norad"), p.norad);
    if (!p.why.isEmpty())
        o.insert(QStringLiteral("why"), p.why.left(400));
    if (p.plan.isValid())
        o.insert(QStringLiteral("planned_worst_deg"), p.predictedWorstDeg);
    if (p.pinned)
        o.insert(QStringLiteral("in_progress"), true);
    return o;
}

std::optional<schedule::ScheduledPass> readPass(const QJsonObject &object, int targets, QString *error)
{
    JsonFields f(object);
    schedule::ScheduledPass p;
    p.target = f.text(QStringLiteral("target"), 100, true).value_or(QString());
    p.priority = int(f.whole(QStringLiteral("priority"), 1, std::max(targets, 1), true).value_or(1)) - 1;
    p.norad = int(f.whole(QStringLiteral("norad"), 1, 999999999).value_or(0));
    const qint64 aos = f.whole(QStringLiteral("aos_ms"), 0, kLatestMs, true).value_or(0);
    const qint64 tca = f.whole(QStringLiteral("tca_ms"), 0, kLatestMs, true).value_or(0);
    const qint64 los = f.whole(QStringLiteral("los_ms"), 0, kLatestMs, true).value_or(0);
    const qint64 start = f.whole(QStringLiteral("start_ms"), 0, kLatestMs, true).value_or(0);
    const qint64 end = f.whole(QStringLiteral("end_ms"), 0, kLatestMs, true).value_or(0);
    if (f.ok() && (los < aos || tca < aos || tca > los || end < start))
        f.fail(QStringLiteral("its times are out of order"));
    p.pass.name = p.target;
    p.pass.catalogueNumber = p.norad;
    p.pass.aos.julian = julianOf(aos);
    p.pass.tca.julian = julianOf(tca);
    p.pass.los.julian = julianOf(los);
    p.startJulian = julianOf(start);
    p.endJulian = julianOf(end);
    p.pass.tca.elevationDeg = f.number(QStringLiteral("max_el"), {-90, 90, "°"}, true).value_or(0);
    p.pass.aos.azimuthDeg = f.number(QStringLiteral("aos_az"), kAzimuth).value_or(0);
    p.pass.los.azimuthDeg = f.number(QStringLiteral("los_az"), kAzimuth).value_or(0);
    p.taken = f.flag(QStringLiteral("taken"), true).value_or(false);
    const QString reason = f.text(QStringLiteral("reason"), 40, true).value_or(QString());
    if (f.ok()) {
        if (const auto r = reasonNamed(reason); !r)
            f.fail(QStringLiteral("'reason' '%1' is not one a schedule gives").arg(reason));
        else if ((*r == schedule::DropReason::None) != p.taken)
            f.fail(QStringLiteral("'reason' and 'taken' disagree"));
        else
            p.reason = *r;
    }
    p.why = f.text(QStringLiteral("why"), 400).value_or(QString());
    p.predictedWorstDeg = f.number(QStringLiteral("planned_worst_deg"), {0, 360, "°"}).value_or(0);
    p.pinned = f.flag(QStringLiteral("in_progress")).value_or(false);
    if (!f.noOthers() || !f.ok()) {
        *error = f.error();
        return std::nullopt;
    }
    return p;
}

// The plan's window, targets, notes and passes, into a schedule's object
// (`current` marked) or a preview's.
void insertPlan(QJsonObject &o, const schedule::Schedule &s, const std::optional<schedule::ScheduledPass> &current)
{
    if (s.settings.startJulian <= 0)
        return; // nothing planned: no window
    o.insert(QStringLiteral("start_ms"), double(unixMs(s.settings.startJulian)));
    o.insert(QStringLiteral("end_ms"), double(unixMs(s.settings.startJulian + s.settings.hours / 24.0)));
    o.insert(QStringLiteral("min_el"), s.settings.minElevationDeg);
    o.insert(QStringLiteral("guard_s"), s.settings.guardSeconds);
    QJsonArray targets;
    for (const QString &t : s.targets.mid(0, kMostScheduleTargets))
        targets.append(t.left(100));
    o.insert(QStringLiteral("targets"), targets);
    QJsonArray notes;
    for (const QString &n : s.notes.mid(0, 20))
        notes.append(n.left(400));
    o.insert(QStringLiteral("notes"), notes);
    QJsonArray passes;
    for (qsizetype i = 0; i < s.passes.size() && i < kMostScheduledPasses; ++i) {
        const schedule::ScheduledPass &p = s.passes[i];
        if (p.priority >= kMostScheduleTargets)
            continue;
        if (current && face::isFollowedPass(p, *current))
            o.insert(QStringLiteral("current"), int(passes.size()));
        passes.append(passObject(p));
    }
    o.insert(QStringLiteral("passes"), passes);
}

// Reads what insertPlan wrote, checking it; says whether there was a window.
// A plan with passes has a window.
bool readPlan(JsonFields &f, schedule::Schedule &s)
{
    const bool planned = f.has(QStringLiteral("passes"));
    const auto start = f.whole(QStringLiteral("start_ms"), 0, kLatestMs, planned);
    const auto end = f.whole(QStringLiteral("end_ms"), 0, kLatestMs, planned);
    if (start.has_value() != end.has_value())
        f.fail(QStringLiteral("'start_ms' and 'end_ms' come together"));
    if (start && end) {
        if (*end <= *start || *end - *start > 14LL * 86400000)
            f.fail(QStringLiteral("'end_ms' is not within 14 days after 'start_ms'"));
        s.settings.startJulian = julianOf(*start);
        s.settings.hours = double(*end - *start) / 3600000.0;
    }
    s.settings.minElevationDeg = f.number(QStringLiteral("min_el"), {-5, 90, "°"}).value_or(0);
    s.settings.guardSeconds = f.number(QStringLiteral("guard_s"), {0, 3600, " s"}).value_or(30);
    s.targets = f.texts(QStringLiteral("targets"), kMostScheduleTargets, 100).value_or(QStringList());
    s.notes = f.texts(QStringLiteral("notes"), 20, 400).value_or(QStringList());
    const auto passes = f.objects(QStringLiteral("passes"), kMostScheduledPasses);
    if (f.ok() && passes) {
        for (qsizetype i = 0; i < passes->size(); ++i) {
            QString why;
            const auto pass = readPass(passes->at(i), int(s.targets.size()), &why);
            if (!pass) {
                f.fail(QStringLiteral("pass %1: %2").arg(i + 1).arg(why));
                break;
            }
            s.passes.append(*pass);
        }
    }
    return start.has_value();
}

} // namespace

QByteArray encodeStationSchedule(qint64 now, qint64 clockMs, double clockRate, bool running, const schedule::Schedule &s,
                                 const std::optional<schedule::ScheduledPass> &current)
{
    QJsonObject o;
    o.insert(QStringLiteral("unix_ms"), double(now));
    o.insert(QStringLiteral("clock_ms"), double(clockMs));
    o.insert(QStringLiteral("clock_rate"), clockRate);
    o.insert(QStringLiteral("running"), running);
    // Running but not planned yet (the first plan is being made): no window.
    if (running && s.settings.startJulian > 0)
        insertPlan(o, s, current);
    return QJsonDocument(o).toJson(QJsonDocument::Compact);
}

QJsonObject schedulePreviewObject(const face::SchedulePreview &preview)
{
    QJsonObject o;
    QJsonArray named;
    for (const face::NamedTarget &t : preview.targets.mid(0, kMostScheduleTargets)) {
        QJsonObject n{{QStringLiteral("asked"), t.asked.left(100)}};
        if (t.isFound()) {
            n.insert(QStringLiteral("name"), t.name.left(100));
            if (t.norad > 0)
                n.insert(QStringLiteral("norad"), t.norad);
        } else {
            n.insert(QStringLiteral("problem"), t.problem.left(400));
        }
        named.append(n);
    }
    o.insert(QStringLiteral("named"), named);
    if (!preview.notPlanned.isEmpty())
        o.insert(QStringLiteral("not_planned"), preview.notPlanned.left(400));
    insertPlan(o, preview.schedule, std::nullopt);
    return o;
}

std::optional<face::SchedulePreview> readSchedulePreview(const QJsonObject &object, QString *error)
{
    JsonFields f(object);
    face::SchedulePreview out;
    const auto named = f.objects(QStringLiteral("named"), kMostScheduleTargets, true);
    for (qsizetype i = 0; named && f.ok() && i < named->size(); ++i) {
        JsonFields n(named->at(i));
        face::NamedTarget t;
        t.asked = n.text(QStringLiteral("asked"), 100, true).value_or(QString());
        t.name = n.text(QStringLiteral("name"), 100).value_or(QString());
        t.norad = int(n.whole(QStringLiteral("norad"), 1, 999999999).value_or(0));
        t.problem = n.text(QStringLiteral("problem"), 400).value_or(QString());
        if (n.ok() && t.name.isEmpty() == t.problem.isEmpty())
            n.fail(QStringLiteral("a target has a name or a problem, one of the two"));
        if (n.ok() && !t.problem.isEmpty() && t.norad > 0)
            n.fail(QStringLiteral("a target not found has no catalogue number"));
        if (!n.noOthers() || !n.ok()) {
            f.fail(QStringLiteral("'named' item %1: %2").arg(i + 1).arg(n.error()));
            break;
        }
        out.targets.append(t);
    }
    out.notPlanned = f.text(QStringLiteral("not_planned"), 400).value_or(QString());
    if (readPlan(f, out.schedule) && !out.notPlanned.isEmpty())
        f.fail(QStringLiteral("a plan, and 'not_planned' too"));
    if (!f.noOthers() || !f.ok()) {
        *error = f.error();
        return std::nullopt;
    }
    return out;
}

std::optional<face::StationSchedule> parseStationSchedule(const QByteArray &payload, QString *error)
{
    std::optional<JsonFields> f = JsonFields::parse(payload, kLargestScheduleMessage, error);
    if (!f)
        return std::nullopt;
    face::StationSchedule out;
    out.unixMs = f->whole(QStringLiteral("unix_ms"), 0, kLatestMs, true).value_or(0);
    out.clockMs = f->whole(QStringLiteral("clock_ms"), 0, kLatestMs).value_or(out.unixMs);
    out.clockRate = f->number(QStringLiteral("clock_rate"), {0, 10000, "x"}).value_or(1);
    out.running = f->flag(QStringLiteral("running"), true).value_or(false);
    schedule::Schedule &s = out.schedule;
    const auto current = f->whole(QStringLiteral("current"), 0, kMostScheduledPasses - 1);
    // A schedule still being planned has no window yet; one with passes has.
    const bool window = readPlan(*f, s);
    out.planned = out.running && window;
    if (!out.running && (window || !s.passes.isEmpty() || !s.targets.isEmpty()))
        f->fail(QStringLiteral("passes in a schedule that is not running"));
    if (f->ok() && current) {
        if (*current >= s.passes.size() || !s.passes.at(int(*current)).taken)
            f->fail(QStringLiteral("'current' is not a taken pass of the list"));
        else
            out.current = int(*current);
    }
    if (!f->noOthers() || !f->ok()) {
        *error = f->error();
        return std::nullopt;
    }
    return out;
}

} // namespace slew::remote
