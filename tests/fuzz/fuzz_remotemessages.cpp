// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzz target: what arrives from an MQTT broker (core/remote): commands to a
// station, a station's state, telemetry, plan and schedule, replies, and a
// broker's address as an operator types it.
//
// Input: the first byte picks the reader (0xfe a plan, 0xff a schedule, any
// other by its remainder of 5), the rest is the message. Checked
// besides crashes and sanitizer reports: every message accepted has every
// number finite and in its range, every text free of control characters
// and within its length, a jog's lease within a second, travel that makes
// sense; what is accepted reads back the same after it is written out (a
// window's command is what the station obeys); a refusal says why in text
// with no control character (it reaches the journal and the window); a
// broker address accepted never carries a password and is plain mqtt://
// only to this machine.
//
// Built with libFuzzer when SLEW_FUZZ is on (packaging/dev.sh fuzz); the
// normal build replays the seed corpus through it (corpusreplay.cpp).

#include "remote/brokeraddress.h"
#include "remote/jsonfields.h"
#include "remote/remotecommand.h"
#include "remote/stationplan.h"
#include "remote/stationschedule.h"
#include "remote/stationstate.h"
#include "remote/stationtelemetry.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

using namespace slew::remote;
using namespace slew::face;

namespace {

[[noreturn]] void fail(const char *what)
{
    std::fprintf(stderr, "fuzz_remotemessages: %s\n", what);
    std::abort();
}

void check(bool ok, const char *what)
{
    if (!ok)
        fail(what);
}

void checkRefusal(const QString &why)
{
    check(!why.isEmpty(), "a refusal without a reason");
    check(JsonFields::isShowable(why, 100000), "a refusal with a control character in it");
}

bool finiteIn(double v, double lo, double hi)
{
    return std::isfinite(v) && v >= lo && v <= hi;
}

void commands(const QByteArray &bytes)
{
    const ParsedCommand parsed = parseRemoteCommand(bytes);
    check(JsonFields::isShowable(parsed.id, kLongestCommandId), "an id too long or with control characters");
    if (!parsed.command) {
        checkRefusal(parsed.error);
        return;
    }
    const RemoteCommand &c = *parsed.command;
    check(finiteIn(c.azimuth, -10000, 10000) && finiteIn(c.elevation, -10000, 10000), "a go-to out of range");
    check(finiteIn(c.azSpeed, -kFastestJog, kFastestJog) && finiteIn(c.elSpeed, -kFastestJog, kFastestJog),
          "a jog too fast");
    check(c.leaseMs >= kShortestJogLeaseMs && c.leaseMs <= kLongestJogLeaseMs, "a lease out of bounds");
    check(JsonFields::isShowable(c.target, kLongestTrackTarget), "a track target too long or with control characters");
    check(!c.minElevation || finiteIn(*c.minElevation, -5, 90), "a minimum elevation out of range");
    check(c.targets.size() <= kMostScheduleTargets, "a schedule of too many targets");
    for (const QString &t : c.targets)
        check(!t.isEmpty() && JsonFields::isShowable(t, kLongestTrackTarget),
              "a schedule's target empty, too long or with control characters");
    check(slew::face::kScheduleHours.contains(c.schedule.hours)
              && slew::face::kScheduleMinElevation.contains(c.schedule.minElevationDeg)
              && slew::face::kScheduleGuard.contains(c.schedule.guardSeconds),
          "a schedule's numbers out of range");
    const ParsedCommand again = parseRemoteCommand(encodeRemoteCommand(c));
    check(again.command.has_value(), "a command written out does not read back");
    const RemoteCommand &b = *again.command;
    check(b.kind == c.kind && b.id == c.id && b.azimuth == c.azimuth && b.elevation == c.elevation
              && b.azSpeed == c.azSpeed && b.elSpeed == c.elSpeed && b.leaseMs == c.leaseMs && b.target == c.target
              && b.minElevation == c.minElevation && b.targets == c.targets && b.held == c.held
              && b.schedule.hours == c.schedule.hours && b.schedule.minElevationDeg == c.schedule.minElevationDeg
              && b.schedule.guardSeconds == c.schedule.guardSeconds,
          "a command reads back different");
}

void states(const QByteArray &bytes)
{
    QString why;
    const auto s = parseStationState(bytes, &why);
    if (!s) {
        checkRefusal(why);
        return;
    }
    check(s->limits.validate().isEmpty(), "a state with travel that makes no sense");
    for (const auto &p : {s->position, s->target, s->park})
        check(!p || (finiteIn(p->x(), -360, 720) && finiteIn(p->y(), -90, 190)), "a state's position out of range");
    check(isLinkStateName(s->link) && isTrackingStateName(s->tracking), "a state with an unknown link or tracking state");
    check(s->radioLink.isEmpty() || isRadioLinkName(s->radioLink), "a state with an unknown radio link state");
    for (const auto &hz : {s->radioReceiveHz, s->radioTransmitHz})
        check(!hz || finiteIn(*hz, 1, 1e12), "a state's radio frequency out of range");
    check(s->alarms.size() <= slew::face::kMostAlarms, "a state with too many alarms");
    for (const QString &text : s->alarms + QStringList{s->linkDetail, s->trackingTarget, s->controllerVersion})
        check(JsonFields::isShowable(text, 400), "a state with text that cannot be shown");
    QString again;
    const auto back = parseStationState(encodeStationState(*s), &again);
    check(back.has_value(), "a state written out does not read back");
    check(encodeStationState(*back) == encodeStationState(*s), "a state reads back different");
}

void telemetry(const QByteArray &bytes)
{
    QString why;
    const auto t = parseTelemetry(bytes, &why);
    if (!t) {
        checkRefusal(why);
        return;
    }
    for (const auto &v : {t->az, t->el, t->commandedAz, t->commandedEl, t->azSpeed, t->elSpeed, t->azLoad, t->elLoad,
                          t->temperature, t->pointingError, t->dopplerRxError, t->dopplerTxError})
        check(!v || std::isfinite(*v), "telemetry with a number that is not finite");
    check((!t->gs || (*t->gs >= 0 && *t->gs <= 0xffff)) && (!t->ge || (*t->ge >= 0 && *t->ge <= 0xffff)),
          "telemetry with a register out of range");
    check(parseTelemetry(encodeTelemetry(*t), &why).has_value(), "telemetry written out does not read back");
}

void replies(const QByteArray &bytes)
{
    QString why;
    const auto r = parseRemoteReply(bytes, &why);
    if (!r) {
        checkRefusal(why);
        return;
    }
    check(JsonFields::isShowable(r->id, kLongestCommandId) && JsonFields::isShowable(r->error, kLongestReplyError),
          "a reply with text that cannot be shown");
    check(r->ok || !r->error.isEmpty(), "a refusal without its reason");
}

void addresses(const QByteArray &bytes)
{
    QString why;
    const auto a = parseBrokerAddress(QString::fromUtf8(bytes), &why);
    if (!a) {
        check(!why.isEmpty(), "an address refused without a reason");
        return;
    }
    check(!a->host.isEmpty() && a->port > 0, "an address without a host or a port");
    check(a->tls || isLoopbackHost(a->host), "plain mqtt:// accepted to a host that is not this machine");
    check(a->stationName.isEmpty() || checkStationName(a->stationName).isEmpty(), "a station name MQTT would misread");
    check(a->caFile.isEmpty() || a->tls, "a CA file without TLS");
}

void plans(const QByteArray &bytes)
{
    QString why;
    const auto p = parseStationPlan(bytes, &why);
    if (!p) {
        checkRefusal(why);
        return;
    }
    check(JsonFields::isShowable(p->target, 100), "a plan's target that cannot be shown");
    check(p->sky.size() <= kMostPlanPoints && p->path.size() <= kMostPlanPoints, "a plan with too many points");
    for (const QList<QPointF> *points : {&p->sky, &p->path}) {
        for (const QPointF &q : *points)
            check(finiteIn(q.x(), -360, 720) && finiteIn(q.y(), -90, 180), "a plan's point out of range");
    }
    check(!p->target.isEmpty() || (p->sky.isEmpty() && p->path.isEmpty()), "a path without a target");
    check(parseStationPlan(encodeStationPlan(*p), &why).has_value(), "a plan written out does not read back");
}

void schedules(const QByteArray &bytes)
{
    QString why;
    const auto s = parseStationSchedule(bytes, &why);
    if (!s) {
        checkRefusal(why);
        return;
    }
    check(s->schedule.passes.size() <= kMostScheduledPasses, "a schedule with too many passes");
    for (const auto &p : s->schedule.passes) {
        check(JsonFields::isShowable(p.target, 100) && JsonFields::isShowable(p.why, 400),
              "a scheduled pass with text that cannot be shown");
        check(p.pass.aos.julian <= p.pass.los.julian && p.startJulian <= p.endJulian, "a pass's times out of order");
        check(p.priority >= 0 && p.priority < std::max<qsizetype>(1, s->schedule.targets.size()),
              "a pass's priority outside the targets");
    }
    check(!s->current || (*s->current < s->schedule.passes.size() && s->schedule.passes.at(*s->current).taken),
          "a current pass that is not a taken one");
    check(std::isfinite(s->schedule.settings.hours) && s->schedule.settings.hours >= 0, "a schedule's hours not finite");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size == 0)
        return 0;
    const QByteArray bytes(reinterpret_cast<const char *>(data) + 1, qsizetype(size - 1));
    if (data[0] == 0xfe) {
        plans(bytes);
        return 0;
    }
    if (data[0] == 0xff) {
        schedules(bytes);
        return 0;
    }
    switch (data[0] % 5) {
    case 0:
        commands(bytes);
        break;
    case 1:
        states(bytes);
        break;
    case 2:
        telemetry(bytes);
        break;
    case 3:
        replies(bytes);
        break;
    default:
        addresses(bytes);
    }
    return 0;
}
