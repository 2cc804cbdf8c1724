// SPDX-License-Identifier: GPL-3.0-or-later
#include "wizard/registernames.h"

#include <QCoreApplication>

namespace slew::ui {

namespace {
constexpr int kAzimuthPark = 7;
constexpr int kElevationPark = 8;
} // namespace

QString registerName(int reg)
{
    static const char *const names[] = {"Az P gain", "Az I gain", "Az D gain", "El P gain",
                                        "El I gain", "El D gain", "Az park",   "El park"};
    if (reg >= 1 && reg <= kElevationPark)
        return QCoreApplication::translate("RegisterNames", names[reg - 1]);
    return QCoreApplication::translate("RegisterNames", "Register %1").arg(reg);
}

QString registerValue(int reg, const QString &value)
{
    const bool angle = reg == kAzimuthPark || reg == kElevationPark;
    return angle ? value + QStringLiteral("°") : value;
}

} // namespace slew::ui
