#include "dialect.h"

#include "operations.h"

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
    case Dialect::Rotctld: return QStringLiteral("rotctld");
    case Dialect::Micro2g: return QStringLiteral("micro2g");
    case Dialect::Rot2Prog: return QStringLiteral("rot2prog");
    case Dialect::Rot1Prog: return QStringLiteral("rot1prog");
    case Dialect::Md01: return QStringLiteral("md01");
    }
    return {};
}

const QList<Dialect> &allDialects()
{
    static const QList<Dialect> all{Dialect::Easycomm1, Dialect::Easycomm2, Dialect::Easycomm3,
                                    Dialect::SatNogs,   Dialect::Gs232A,    Dialect::Gs232B,
                                    Dialect::Rotctld,   Dialect::Micro2g,   Dialect::Rot2Prog,
                                    Dialect::Rot1Prog,  Dialect::Md01};
    return all;
}

QString dialectNameList()
{
    QStringList names;
    for (Dialect d : allDialects())
        names << dialectName(d);
    return names.join(QStringLiteral(", "));
}

bool isAzimuthOnly(Dialect d)
{
    return d == Dialect::Micro2g || d == Dialect::Rot1Prog;
}

int rotorsOnLine(Dialect d)
{
    return d == Dialect::Micro2g ? 4 : 1;
}

// Micro-2g counts here too: its go-to names one rotor's azimuth, and the
// session then treats the (always 0) elevation as the other axis. A SPID set
// frame always carries both (Rot1Prog: the azimuth alone, as Micro-2g).
bool setsBothAxesTogether(Dialect d)
{
    return d == Dialect::Easycomm1 || isGs232(d) || d == Dialect::Rotctld || d == Dialect::Micro2g || isSpid(d);
}

char lineTerminator(Dialect d)
{
    if (isSpid(d))
        return '\0';
    return isGs232(d) || d == Dialect::Micro2g ? '\r' : '\n';
}

std::optional<Dialect> dialectFromName(QStringView name)
{
    for (Dialect d : allDialects()) {
        if (name.compare(dialectName(d), Qt::CaseInsensitive) == 0)
            return d;
    }
    return std::nullopt;
}

namespace {

// SPID is not in the operations table: its commands are frames, not
// mnemonics. A frame sets, asks or stops both axes at once; Rot1Prog has no
// elevation. No speeds, registers, park or version. The MD-01/02 has a move
// command (spid::encodeMove), one direction bit per axis.
bool spidSupports(Dialect d, Op op)
{
    switch (op) {
    case Op::Azimuth:
    case Op::StopAzimuth: return true;
    case Op::Elevation:
    case Op::StopElevation: return d != Dialect::Rot1Prog;
    case Op::MoveLeft:
    case Op::MoveRight:
    case Op::MoveUp:
    case Op::MoveDown: return d == Dialect::Md01;
    default: return false;
    }
}

} // namespace

bool dialectSupports(Dialect d, Op op)
{
    const OperationInfo &info = operationInfo(op);
    if (isSpid(d))
        return spidSupports(d, op);
    if (d == Dialect::Rotctld)
        return info.rotctld;
    if (d == Dialect::Micro2g)
        return info.micro2g;
    if (isGs232(d))
        return info.gs232;
    switch (info.easycomm) {
    case EasycommReach::None: return false;
    case EasycommReach::All: return true;
    case EasycommReach::FromEasycomm2: return d != Dialect::Easycomm1;
    case EasycommReach::Easycomm3AndSatNogs: return d == Dialect::Easycomm3 || d == Dialect::SatNogs;
    case EasycommReach::Easycomm3Only: return d == Dialect::Easycomm3;
    }
    return false;
}

int angleDecimals(Dialect d)
{
    if (isGs232(d) || d == Dialect::Micro2g || d == Dialect::Rot1Prog)
        return 0; // whole degrees: W010 020, M035, a Rot1Prog set
    if (isSpid(d))
        return 1; // a Rot2Prog or MD-01 reply is in tenths
    if (d == Dialect::Rotctld)
        return 2; // as rotctld prints its own answers
    return d == Dialect::Easycomm3 ? 2 : 1;
}

} // namespace slew::protocol
