// SPDX-License-Identifier: GPL-3.0-or-later
#include "radiolimits.h"

#include <QCoreApplication>

namespace slew::radio::limits {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("RadioLimits", text);
}

// Letters and digits only, not too long (kMaxModeChars says why).
bool isModeName(const QString &mode)
{
    if (mode.isEmpty() || mode.size() > kMaxModeChars)
        return false;
    for (const QChar c : mode) {
        if (!(c.isDigit() || (c >= u'A' && c <= u'Z') || (c >= u'a' && c <= u'z')))
            return false;
    }
    return true;
}

} // namespace

QString frequencyRefusal(double hz)
{
    QString why;
    if (input::checkNumber(hz, kFrequencyRange, &why))
        return {};
    return tr("not sent: %1").arg(why);
}

QString modeRefusal(const QString &mode, int passbandHz)
{
    if (!isModeName(mode))
        return tr("not sent: a mode is a Hamlib mode name of letters and digits (USB, FM, PKTUSB)");
    if (passbandHz < kMinPassbandHz || passbandHz > kMaxPassbandHz)
        return tr("not sent: a passband is from %1 to %2 Hz (0: the mode's default)")
            .arg(kMinPassbandHz)
            .arg(kMaxPassbandHz);
    return {};
}

} // namespace slew::radio::limits
