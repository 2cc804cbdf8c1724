#include "dialect.h"

#include "operations.h"

#include <QStringList>

#include <iterator>

namespace slew::protocol {

// The table is indexed by the enum: each row in its own place.
static_assert([] {
    for (std::size_t i = 0; i < std::size(kDialects); ++i)
        if (static_cast<std::size_t>(kDialects[i].dialect) != i)
            return false;
    return true;
}());
static_assert(std::size(kDialects) == static_cast<std::size_t>(Dialect::Md01) + 1, "a dialect without a row");

QString dialectName(Dialect d)
{
    return QString::fromLatin1(dialectRow(d).name);
}

const QList<Dialect> &allDialects()
{
    static const QList<Dialect> all = [] {
        QList<Dialect> list;
        for (const DialectRow &row : kDialects)
            list << row.dialect;
        return list;
    }();
    return all;
}

QString dialectNameList()
{
    QStringList names;
    for (Dialect d : allDialects())
        names << dialectName(d);
    return names.join(QStringLiteral(", "));
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

} // namespace slew::protocol
