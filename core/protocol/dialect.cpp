#include "dialect.h"

namespace slew::protocol {

QString dialectName(Dialect d)
{
    switch (d) {
    case Dialect::Easycomm1: return QStringLiteral("easycomm1");
    case Dialect::Easycomm2: return QStringLiteral("easycomm2");
    case Dialect::Easycomm3: return QStringLiteral("easycomm3");
    case Dialect::SatNogs: return QStringLiteral("satnogs");
    }
    return {};
}

std::optional<Dialect> dialectFromName(QStringView name)
{
    for (Dialect d : {Dialect::Easycomm1, Dialect::Easycomm2, Dialect::Easycomm3, Dialect::SatNogs}) {
        if (name.compare(dialectName(d), Qt::CaseInsensitive) == 0)
            return d;
    }
    return std::nullopt;
}

bool dialectSupports(Dialect d, Op op)
{
    switch (op) {
    case Op::Invalid:
    case Op::ConfigValue: // a reply, never sent by the host
    case Op::Alarm:       // likewise
        return false;
    case Op::Azimuth:
    case Op::Elevation:
    case Op::UplinkFreq:
    case Op::DownlinkFreq:
    case Op::UplinkMode:
    case Op::DownlinkMode:
        return true; // all four carry these, Easycomm I inside its one line
    case Op::UplinkRadio:
    case Op::DownlinkRadio:
    case Op::MoveLeft:
    case Op::MoveRight:
    case Op::MoveUp:
    case Op::MoveDown:
    case Op::StopAzimuth:
    case Op::StopElevation:
    case Op::Aos:
    case Op::Los:
    case Op::SetOutput:
    case Op::ReadInput:
    case Op::ReadAnalog:
    case Op::Time:
    case Op::Version:
        return d != Dialect::Easycomm1;
    case Op::VelocityLeft:
    case Op::VelocityRight:
    case Op::VelocityUp:
    case Op::VelocityDown:
    case Op::ConfigRead:
    case Op::ConfigWrite:
    case Op::Status:
    case Op::ErrorFlags:
        return d == Dialect::Easycomm3 || d == Dialect::SatNogs;
    case Op::Reset:
    case Op::Park:
        return d != Dialect::Easycomm1; // Hamlib sends both to models 202 and 204
    case Op::Encoders:
        return d == Dialect::Easycomm3;
    }
    return false;
}

int angleDecimals(Dialect d)
{
    return d == Dialect::Easycomm3 ? 2 : 1;
}

} // namespace slew::protocol
