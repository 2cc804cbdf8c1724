#include "sessiontypes.h"

#include <QStringList>

namespace slew::session {

QString describeErrorFlags(int ge)
{
    QStringList parts;
    if (ge & ErrorSensor)
        parts << QStringLiteral("sensor error");
    if (ge & ErrorHoming)
        parts << QStringLiteral("homing error");
    if (ge & ErrorMotor)
        parts << QStringLiteral("motor error");
    if (ge & ErrorWatchdog)
        parts << QStringLiteral("watchdog");
    if ((ge & ErrorOverTemperature) == ErrorOverTemperature)
        parts << QStringLiteral("possible over-temperature");
    if (ge & ~0x1f)
        parts << QStringLiteral("unknown error bits 0x%1").arg(ge & ~0x1f, 0, 16);
    return parts.join(QStringLiteral(", "));
}

QString describeAxisStatus(quint8 bits)
{
    QStringList parts;
    if (bits & StatusIdle)
        parts << QStringLiteral("idle");
    if (bits & StatusMoving)
        parts << QStringLiteral("moving");
    if (bits & StatusPointing)
        parts << QStringLiteral("pointing");
    if (bits & StatusError)
        parts << QStringLiteral("error");
    return parts.isEmpty() ? QStringLiteral("none") : parts.join(QStringLiteral(", "));
}

} // namespace slew::session
