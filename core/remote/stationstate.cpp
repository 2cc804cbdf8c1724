// SPDX-License-Identifier: GPL-3.0-or-later
#include "stationstate.h"

#include "jsonfields.h"

#include "sky/utctime.h"

#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace slew::remote {
namespace {

// Any rotator's travel fits these: 450° overlaps, south stops, 180° flips.
constexpr input::NumberRange kAzimuth{-360, 720, "°"};
constexpr input::NumberRange kElevation{-90, 190, "°"};
constexpr qint64 kLatestMs = 32503680000000LL; // the year 3000
// What any radio link takes (radio/radiolimits.h's kFrequencyRange).
constexpr input::NumberRange kRadioHz{1, 1e12, " Hz"};

void putPoint(QJsonObject &o, const char *az, const char *el, const std::optional<QPointF> &p)
{
    if (!p)
        return;
    o.insert(QLatin1String(az), p->x());
    o.insert(QLatin1String(el), p->y());
}

std::optional<QPointF> takePoint(JsonFields &f, const char *az, const char *el)
{
    const auto a = f.number(QLatin1String(az), kAzimuth);
    const auto e = f.number(QLatin1String(el), kElevation);
    if (a.has_value() != e.has_value()) {
        f.fail(QStringLiteral("'%1' and '%2' come together").arg(QLatin1String(az), QLatin1String(el)));
        return std::nullopt;
    }
    return a ? std::optional<QPointF>(QPointF(*a, *e)) : std::nullopt;
}

} // namespace

bool isLinkStateName(const QString &name)
{
    return name == u"disconnected" || name == u"connecting" || name == u"connected" || name == u"reconnecting";
}

bool isRadioLinkName(const QString &name)
{
    return name == u"none" || isLinkStateName(name);
}

bool isTrackingStateName(const QString &name)
{
    return name == u"off" || name == u"planning" || name == u"waiting" || name == u"tracking" || name == u"done";
}

QByteArray encodeStationState(const face::StationState &s)
{
    QJsonObject o;
    o.insert(QStringLiteral("unix_ms"), double(s.unixMs));
    o.insert(QStringLiteral("time"),
             sky::utcFromUnixMs(s.unixMs).toString(Qt::ISODateWithMs));
    o.insert(QStringLiteral("link"), s.link);
    if (!s.linkDetail.isEmpty())
        o.insert(QStringLiteral("link_detail"), s.linkDetail);
    putPoint(o, "az", "el", s.position);
    o.insert(QStringLiteral("stale"), s.stale);
    putPoint(o, "target_az", "target_el", s.target);
    o.insert(QStringLiteral("moving"), s.moving);
    if (s.azimuthStatus)
        o.insert(QStringLiteral("az_status"), *s.azimuthStatus);
    if (s.elevationStatus)
        o.insert(QStringLiteral("el_status"), *s.elevationStatus);
    o.insert(QStringLiteral("axis_error"), s.axisError);
    o.insert(QStringLiteral("homing_failed"), s.homingFailed);
    if (!s.controllerErrors.isEmpty())
        o.insert(QStringLiteral("controller_errors"), s.controllerErrors);
    o.insert(QStringLiteral("az_min"), s.limits.azMin);
    o.insert(QStringLiteral("az_max"), s.limits.azMax);
    o.insert(QStringLiteral("el_min"), s.limits.elMin);
    o.insert(QStringLiteral("el_max"), s.limits.elMax);
    if (!(s.profileLimits == s.limits)) {
        o.insert(QStringLiteral("profile_az_min"), s.profileLimits.azMin);
        o.insert(QStringLiteral("profile_az_max"), s.profileLimits.azMax);
        o.insert(QStringLiteral("profile_el_min"), s.profileLimits.elMin);
        o.insert(QStringLiteral("profile_el_max"), s.profileLimits.elMax);
    }
    putPoint(o, "park_az", "park_el", s.park);
    o.insert(QStringLiteral("azimuth_only"), s.azimuthOnly);
    if (!s.dialect.isEmpty())
        o.insert(QStringLiteral("dialect"), s.dialect);
    o.insert(QStringLiteral("probed"), s.probed);
    o.insert(QStringLiteral("jog_speed"), s.jogSpeed);
    o.insert(QStringLiteral("can_home"), s.canHome);
    o.insert(QStringLiteral("park_command"), s.parkCommand);
    o.insert(QStringLiteral("tracking"), s.tracking);
    if (!s.trackingTarget.isEmpty())
        o.insert(QStringLiteral("tracking_target"), s.trackingTarget);
    if (s.trackingNorad)
        o.insert(QStringLiteral("tracking_norad"), *s.trackingNorad);
    if (s.clockMs) {
        o.insert(QStringLiteral("clock_ms"), double(*s.clockMs));
        o.insert(QStringLiteral("clock_rate"), s.clockRate);
    }
    if (s.passAosMs)
        o.insert(QStringLiteral("pass_aos_ms"), double(*s.passAosMs));
    if (s.passLosMs)
        o.insert(QStringLiteral("pass_los_ms"), double(*s.passLosMs));
    if (s.passMaxElevation)
        o.insert(QStringLiteral("pass_max_el"), *s.passMaxElevation);
    o.insert(QStringLiteral("alarms"), QJsonArray::fromStringList(s.alarms.mid(0, face::kMostAlarms)));
    o.insert(QStringLiteral("severe"), s.severe);
    o.insert(QStringLiteral("operator_hold"), s.operatorHold);
    if (s.motionHeld)
        o.insert(QStringLiteral("motion_held"), true);
    if (!s.controllerVersion.isEmpty())
        o.insert(QStringLiteral("controller"), s.controllerVersion);
    o.insert(QStringLiteral("slew"), s.slewVersion);
    if (!s.radioLink.isEmpty()) {
        o.insert(QStringLiteral("radio_link"), s.radioLink);
        o.insert(QStringLiteral("radio_held"), s.radioHeld);
        o.insert(QStringLiteral("radio_steering"), s.radioSteering);
        if (s.radioReceiveHz)
            o.insert(QStringLiteral("radio_rx_hz"), *s.radioReceiveHz);
        if (s.radioTransmitHz)
            o.insert(QStringLiteral("radio_tx_hz"), *s.radioTransmitHz);
    }
    return QJsonDocument(o).toJson(QJsonDocument::Compact);
}

std::optional<face::StationState> parseStationState(const QByteArray &payload, QString *error)
{
    auto parsed = JsonFields::parse(payload, kLargestStateMessage, error);
    if (!parsed)
        return std::nullopt;
    JsonFields &f = *parsed;
    face::StationState s;
    s.unixMs = f.whole(QStringLiteral("unix_ms"), 0, kLatestMs, true).value_or(0);
    f.text(QStringLiteral("time"), 40); // for people; unix_ms is the one read
    s.link = f.text(QStringLiteral("link"), 20, true).value_or(QString());
    if (f.ok() && !isLinkStateName(s.link))
        f.fail(QStringLiteral("'link' is not disconnected, connecting, connected or reconnecting"));
    s.linkDetail = f.text(QStringLiteral("link_detail"), 400).value_or(QString());
    s.position = takePoint(f, "az", "el");
    s.stale = f.flag(QStringLiteral("stale")).value_or(true);
    s.target = takePoint(f, "target_az", "target_el");
    s.moving = f.flag(QStringLiteral("moving")).value_or(false);
    s.azimuthStatus = f.text(QStringLiteral("az_status"), 100);
    s.elevationStatus = f.text(QStringLiteral("el_status"), 100);
    s.axisError = f.flag(QStringLiteral("axis_error")).value_or(false);
    s.homingFailed = f.flag(QStringLiteral("homing_failed")).value_or(false);
    s.controllerErrors = f.text(QStringLiteral("controller_errors"), 400).value_or(QString());
    s.limits.azMin = f.number(QStringLiteral("az_min"), kAzimuth, true).value_or(0);
    s.limits.azMax = f.number(QStringLiteral("az_max"), kAzimuth, true).value_or(360);
    s.limits.elMin = f.number(QStringLiteral("el_min"), kElevation, true).value_or(0);
    s.limits.elMax = f.number(QStringLiteral("el_max"), kElevation, true).value_or(90);
    // Only when it differs from the travel in force.
    s.profileLimits.azMin = f.number(QStringLiteral("profile_az_min"), kAzimuth).value_or(s.limits.azMin);
    s.profileLimits.azMax = f.number(QStringLiteral("profile_az_max"), kAzimuth).value_or(s.limits.azMax);
    s.profileLimits.elMin = f.number(QStringLiteral("profile_el_min"), kElevation).value_or(s.limits.elMin);
    s.profileLimits.elMax = f.number(QStringLiteral("profile_el_max"), kElevation).value_or(s.limits.elMax);
    if (f.ok()) {
        if (const QString why = s.limits.validate(); !why.isEmpty())
            f.fail(QStringLiteral("the travel: %1").arg(why));
        else if (const QString bad = s.profileLimits.validate(); !bad.isEmpty())
            f.fail(QStringLiteral("the profile's travel: %1").arg(bad));
    }
    s.park = takePoint(f, "park_az", "park_el");
    s.azimuthOnly = f.flag(QStringLiteral("azimuth_only")).value_or(false);
    // A station older than these fields says none of them: what most can.
    s.dialect = f.text(QStringLiteral("dialect"), 60).value_or(QString());
    s.probed = f.flag(QStringLiteral("probed")).value_or(false);
    s.jogSpeed = f.flag(QStringLiteral("jog_speed")).value_or(true);
    s.canHome = f.flag(QStringLiteral("can_home")).value_or(true);
    s.parkCommand = f.flag(QStringLiteral("park_command")).value_or(true);
    s.tracking = f.text(QStringLiteral("tracking"), 20).value_or(QStringLiteral("off"));
    if (f.ok() && !isTrackingStateName(s.tracking))
        f.fail(QStringLiteral("'tracking' is not off, planning, waiting, tracking or done"));
    s.trackingTarget = f.text(QStringLiteral("tracking_target"), 100).value_or(QString());
    if (const auto norad = f.whole(QStringLiteral("tracking_norad"), 1, 999999999))
        s.trackingNorad = int(*norad);
    s.clockMs = f.whole(QStringLiteral("clock_ms"), 0, kLatestMs);
    s.clockRate = f.number(QStringLiteral("clock_rate"), {0, kMostClockRate, "x"}).value_or(1.0);
    s.passAosMs = f.whole(QStringLiteral("pass_aos_ms"), 0, kLatestMs);
    s.passLosMs = f.whole(QStringLiteral("pass_los_ms"), 0, kLatestMs);
    s.passMaxElevation = f.number(QStringLiteral("pass_max_el"), {-90, 90, "°"});
    s.alarms = f.texts(QStringLiteral("alarms"), face::kMostAlarms, 400).value_or(QStringList());
    s.severe = f.flag(QStringLiteral("severe")).value_or(false);
    s.operatorHold = f.flag(QStringLiteral("operator_hold")).value_or(false);
    s.motionHeld = f.flag(QStringLiteral("motion_held")).value_or(false);
    s.controllerVersion = f.text(QStringLiteral("controller"), 100).value_or(QString());
    s.slewVersion = f.text(QStringLiteral("slew"), 40).value_or(QString());
    // A station older than the radio's fields says none of them.
    s.radioLink = f.text(QStringLiteral("radio_link"), 20).value_or(QString());
    if (f.ok() && f.has(QStringLiteral("radio_link")) && !isRadioLinkName(s.radioLink))
        f.fail(QStringLiteral("'radio_link' is not none, disconnected, connecting, connected or reconnecting"));
    s.radioHeld = f.flag(QStringLiteral("radio_held")).value_or(false);
    s.radioSteering = f.flag(QStringLiteral("radio_steering")).value_or(false);
    s.radioReceiveHz = f.number(QStringLiteral("radio_rx_hz"), kRadioHz);
    s.radioTransmitHz = f.number(QStringLiteral("radio_tx_hz"), kRadioHz);
    if (f.ok() && s.radioLink.isEmpty()) {
        for (const char *key : {"radio_held", "radio_steering", "radio_rx_hz", "radio_tx_hz"}) {
            if (f.has(QLatin1String(key)))
                f.fail(QStringLiteral("'%1' comes with 'radio_link'").arg(QLatin1String(key)));
        }
    }
    if (!f.noOthers()) {
        *error = f.error();
        return std::nullopt;
    }
    return s;
}

} // namespace slew::remote
