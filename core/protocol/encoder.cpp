#include "encoder.h"

#include <cmath>
#include <cstdio>

namespace slew::protocol {

QByteArray formatNumber(double value, int decimals)
{
    // A value that rounds to zero is written as zero: "-0.0" reads as a
    // negative angle to some device parsers.
    if (!std::isfinite(value) || std::fabs(value) < 0.5 * std::pow(10.0, -decimals))
        value = 0.0;
    // snprintf with "C" numbers: the wire always uses '.', never a locale comma.
    char buffer[64];
    const int n = std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    return QByteArray(buffer, n > 0 ? n : 0);
}

namespace {

QByteArray integer(double v)
{
    return QByteArray::number(qint64(std::llround(v)));
}

// Velocity in mdeg/s. The seeds/000 controller pads to 3 digits, Hamlib's
// model 204 (the SatNOGS path) to 4; devices read either.
QByteArray velocity(double mdegPerSecond, Dialect d)
{
    char buffer[32];
    const long long v = std::llabs(std::llround(mdegPerSecond));
    const int n = std::snprintf(buffer, sizeof buffer, d == Dialect::SatNogs ? "%04lld" : "%03lld", v);
    return QByteArray(buffer, n);
}

} // namespace

QByteArray encodeToken(const Message &m, Dialect d)
{
    if (!dialectSupports(d, m.op))
        return {};
    QByteArray out = mnemonic(m.op).toByteArray();
    switch (m.op) {
    case Op::Azimuth:
    case Op::Elevation:
        if (m.hasValue)
            out += formatNumber(m.value, angleDecimals(d));
        break;
    case Op::UplinkFreq:
    case Op::DownlinkFreq:
    case Op::UplinkRadio:
    case Op::DownlinkRadio:
    case Op::Status:
    case Op::ErrorFlags:
        if (m.hasValue)
            out += integer(m.value);
        break;
    case Op::UplinkMode:
    case Op::DownlinkMode:
    case Op::Time:
    case Op::Version:
        out += m.text.view();
        break;
    case Op::VelocityLeft:
    case Op::VelocityRight:
    case Op::VelocityUp:
    case Op::VelocityDown:
        if (m.hasValue)
            out += velocity(m.value, d);
        break;
    case Op::SetOutput:
        out += QByteArray::number(m.index) + ',' + integer(m.value);
        break;
    case Op::ReadInput:
    case Op::ReadAnalog:
        out += QByteArray::number(m.index);
        break;
    case Op::ConfigRead:
        // SatNOGS firmware reads the register after a space: `CR 1`.
        if (d == Dialect::SatNogs)
            out += ' ';
        out += QByteArray::number(m.index);
        break;
    case Op::ConfigWrite:
        out += QByteArray::number(m.index) + ',';
        out += m.text.isEmpty() ? formatNumber(m.value, 3) : m.text.view().toByteArray();
        break;
    case Op::Encoders:
    case Op::MoveLeft:
    case Op::MoveRight:
    case Op::MoveUp:
    case Op::MoveDown:
    case Op::StopAzimuth:
    case Op::StopElevation:
    case Op::Aos:
    case Op::Los:
    case Op::Reset:
    case Op::Park:
        break;
    case Op::Invalid:
    case Op::Alarm:
    case Op::ConfigValue:
        return {};
    }
    return out;
}

QByteArray encodeLine(std::initializer_list<Message> tokens, Dialect d)
{
    QByteArray line;
    for (const Message &m : tokens) {
        const QByteArray token = encodeToken(m, d);
        if (token.isEmpty())
            return {};
        if (!line.isEmpty())
            line += ' ';
        line += token;
    }
    if (!line.isEmpty())
        line += '\n';
    return line;
}

QByteArray encodeEasycomm1Line(double az, double el, quint64 up, QByteArrayView upMode, quint64 down,
                               QByteArrayView downMode)
{
    QByteArray line = "AZ" + formatNumber(az, 1) + " EL" + formatNumber(el, 1);
    line += " UP" + QByteArray::number(up).rightJustified(3, '0') + ' ' + upMode.toByteArray();
    line += " DN" + QByteArray::number(down).rightJustified(3, '0') + ' ' + downMode.toByteArray();
    line += '\n';
    return line;
}

QByteArray encodeSetPosition(double az, double el, Dialect d)
{
    if (d == Dialect::Easycomm1)
        return encodeEasycomm1Line(az, el);
    return encodeLine({Message::number(Op::Azimuth, az), Message::number(Op::Elevation, el)}, d);
}

QByteArray encodeQueryPosition(Dialect d)
{
    if (d == Dialect::Easycomm1)
        return {}; // Easycomm I has no way to ask
    return encodeLine({Message::query(Op::Azimuth), Message::query(Op::Elevation)}, d);
}

QByteArray encodeStop(bool azimuth, bool elevation, Dialect d)
{
    if (d == Dialect::Easycomm1 || (!azimuth && !elevation))
        return {};
    if (azimuth && elevation)
        return encodeLine({Message::query(Op::StopAzimuth), Message::query(Op::StopElevation)}, d);
    return encodeLine({Message::query(azimuth ? Op::StopAzimuth : Op::StopElevation)}, d);
}

} // namespace slew::protocol
