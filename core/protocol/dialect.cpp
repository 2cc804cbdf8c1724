#include "dialect.h"

#include <QStringList>

namespace slew::protocol {

QString dialectName(Dialect d)
{
    switch (d) {
    case Dialect::Easycomm1: return QStringLiteral("easycomm1");
    case Dialect::Easycomm2: return QStringLiteral("easycomm2");
    case Dialect::Easycomm3: return QStringLiteral("easycomm3");
    case Dialect::SatNogs: return QStringLiteral("satnogs");
    case Dialect::Gs232A: return QStringLiteral("gs232a");
    case Dialect::Gs232B: return QStringLiteral("gs232b");
    }
    return {};
}

const QList<Dialect> &allDialects()
{
    static const QList<Dialect> all{Dialect::Easycomm1, Dialect::Easycomm2, Dialect::Easycomm3,
                                    Dialect::SatNogs,   Dialect::Gs232A,    Dialect::Gs232B};
    return all;
}

QString dialectNameList()
{
    QStringList names;
    for (Dialect d : allDialects())
        names << dialectName(d);
    return names.join(QStringLiteral(", "));
}

bool isGs232(Dialect d)
{
    return d == Dialect::Gs232A || d == Dialect::Gs232B;
}

char lineTerminator(Dialect d)
{
    return isGs232(d) ? '\r' : '\n';
}

std::optional<Dialect> dialectFromName(QStringView name)
{
    for (Dialect d : allDialects()) {
        if (name.compare(dialectName(d), Qt::CaseInsensitive) == 0)
            return d;
    }
    return std::nullopt;
}

bool dialectSupports(Dialect d, Op op)
{
    if (isGs232(d)) {
        switch (op) {
        case Op::Azimuth:   // M (set), C (query)
        case Op::Elevation: // B (query); set only together with azimuth (W)
        case Op::MoveLeft:
        case Op::MoveRight:
        case Op::MoveUp:
        case Op::MoveDown:
        case Op::StopAzimuth:   // A
        case Op::StopElevation: // E
        case Op::Speed:         // X1..X4
        case Op::KeepAlive:     // ?  (easycom library)
            return true;
        default:
            return false;
        }
    }
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
    case Op::Speed:
    case Op::KeepAlive:
        return false;
    }
    return false;
}

int angleDecimals(Dialect d)
{
    if (isGs232(d))
        return 0; // whole degrees: W010 020
    return d == Dialect::Easycomm3 ? 2 : 1;
}

} // namespace slew::protocol
