// SPDX-License-Identifier: GPL-3.0-or-later
#include "stationtelemetry.h"

#include "jsonfields.h"

#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>

namespace slew::remote {
namespace {

// What one sample's fields are called and may hold.
struct Field {
    const char *key;
    std::optional<double> face::TelemetrySample::*member;
    input::NumberRange range;
};

const Field kFields[] = {
    {"az", &face::TelemetrySample::az, {-360, 720, "°"}},
    {"el", &face::TelemetrySample::el, {-90, 190, "°"}},
    {"commanded_az", &face::TelemetrySample::commandedAz, {-360, 720, "°"}},
    {"commanded_el", &face::TelemetrySample::commandedEl, {-90, 190, "°"}},
    {"az_speed", &face::TelemetrySample::azSpeed, {-1000, 1000, "°/s"}},
    {"el_speed", &face::TelemetrySample::elSpeed, {-1000, 1000, "°/s"}},
    {"az_load", &face::TelemetrySample::azLoad, {-1e6, 1e6, ""}},
    {"el_load", &face::TelemetrySample::elLoad, {-1e6, 1e6, ""}},
    {"temperature", &face::TelemetrySample::temperature, {-100, 300, " °C"}},
    {"pointing_error", &face::TelemetrySample::pointingError, {0, 180, "°"}},
    {"doppler_rx_error", &face::TelemetrySample::dopplerRxError, {-1e9, 1e9, " Hz"}},
    {"doppler_tx_error", &face::TelemetrySample::dopplerTxError, {-1e9, 1e9, " Hz"}},
};

} // namespace

QByteArray encodeTelemetry(const face::TelemetrySample &s)
{
    QJsonObject o;
    o.insert(QStringLiteral("unix_ms"), double(s.unixMs));
    for (const Field &field : kFields) {
        const std::optional<double> &v = s.*(field.member);
        if (v && std::isfinite(*v))
            o.insert(QLatin1String(field.key), *v);
    }
    if (s.gs)
        o.insert(QStringLiteral("gs"), *s.gs);
    if (s.ge)
        o.insert(QStringLiteral("ge"), *s.ge);
    return QJsonDocument(o).toJson(QJsonDocument::Compact);
}

std::optional<face::TelemetrySample> parseTelemetry(const QByteArray &payload, QString *error)
{
    auto parsed = JsonFields::parse(payload, kLargestTelemetryMessage, error);
    if (!parsed)
        return std::nullopt;
    JsonFields &f = *parsed;
    face::TelemetrySample s;
    s.unixMs = f.whole(QStringLiteral("unix_ms"), 0, 32503680000000LL, true).value_or(0);
    for (const Field &field : kFields)
        s.*(field.member) = f.number(QLatin1String(field.key), field.range);
    if (const auto gs = f.whole(QStringLiteral("gs"), 0, 0xffff))
        s.gs = int(*gs);
    if (const auto ge = f.whole(QStringLiteral("ge"), 0, 0xffff))
        s.ge = int(*ge);
    if (!f.noOthers()) {
        *error = f.error();
        return std::nullopt;
    }
    return s;
}

} // namespace slew::remote
