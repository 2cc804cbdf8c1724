// SPDX-License-Identifier: GPL-3.0-or-later
#include "radioplan.h"

#include "input/finitenumber.h"
#include "input/logtext.h"

#include <QObject>
#include <QRegularExpression>

#include <cmath>

namespace slew::radio {

namespace {

constexpr double kLargestOffsetHz = 1e6;

// The mode names a transponder list uses that Hamlib knows as they are.
QString hamlibMode(const QString &mode)
{
    static const QStringList kSame = {QStringLiteral("USB"), QStringLiteral("LSB"), QStringLiteral("CW"),
                                      QStringLiteral("FM"), QStringLiteral("AM")};
    const QString upper = mode.trimmed().toUpper();
    return kSame.contains(upper) ? upper : QString();
}

// "SSB", "SSB/CW", "LSB/USB", "USB/CW": a linear transponder's passband modes.
bool isSideband(const QString &mode)
{
    const QString upper = mode.trimmed().toUpper();
    return upper.contains(QLatin1String("SSB")) || upper.contains(QLatin1String("USB"))
           || upper.contains(QLatin1String("LSB"));
}

// Hertz in a number and its unit, any sign; nothing with *error otherwise.
std::optional<double> hertzIn(const QString &text, QString *error)
{
    static const QRegularExpression kForm(QStringLiteral("^\\s*([-+]?[0-9.eE+-]+)\\s*([kKmMgG]?)(?:[hH][zZ])?\\s*$"));
    const QRegularExpressionMatch m = kForm.match(text);
    const std::optional<double> number = m.hasMatch() ? input::finiteNumber(m.captured(1)) : std::nullopt;
    if (!number) {
        *error = QObject::tr("'%1' is not a frequency (145.8M, 435.125 MHz, 1296200k, or hertz)")
                     .arg(input::loggableText(text, 40));
        return std::nullopt;
    }
    double scale = 1;
    const QString unit = m.captured(2).toLower();
    switch (unit.isEmpty() ? u' ' : unit.front().unicode()) {
    case u'k':
        scale = 1e3;
        break;
    case u'm':
        scale = 1e6;
        break;
    case u'g':
        scale = 1e9;
        break;
    default:
        break;
    }
    return *number * scale;
}

} // namespace

std::optional<Passband> passbandAround(const QList<Transponder> &transponders, double downlinkHz)
{
    for (const Transponder &t : transponders) {
        if (t.isLinear() && t.downlinkContains(downlinkHz))
            return Passband{*t.downlinkLowHz, *t.downlinkHighHz};
    }
    return std::nullopt;
}

std::optional<RadioPlan> planFor(const Transponder &t, QString *note, QString *error)
{
    if (!t.downlinkLowHz) {
        if (error)
            *error = QObject::tr("%1 has no downlink to tune").arg(t.displayName());
        return std::nullopt;
    }
    RadioPlan plan;
    plan.name = t.displayName();
    plan.noradId = t.noradId;
    SatelliteFrequencies &f = plan.frequencies;
    if (t.isLinear()) {
        f.downlinkHz = (*t.downlinkLowHz + *t.downlinkHighHz) / 2;
        if (t.hasUplink()) {
            f.uplinkHz = t.uplinkForDownlink(f.downlinkHz);
            f.uplinkFollows = t.inverting ? UplinkFollowsDial::OppositeWay : UplinkFollowsDial::SameWay;
        }
        f.downlinkPassband = Passband{*t.downlinkLowHz, *t.downlinkHighHz};
    } else {
        f.downlinkHz = *t.downlinkLowHz;
        if (t.hasUplink())
            f.uplinkHz = *t.uplinkLowHz;
    }
    if (isSideband(t.mode) && hamlibMode(t.mode) != QLatin1String("LSB")) {
        // An SSB passband: upper sideband down; an inverting transponder
        // turns the uplink's lower sideband into it.
        plan.receiveMode = QStringLiteral("USB");
        if (f.uplinkHz)
            plan.transmitMode = t.inverting ? QStringLiteral("LSB") : QStringLiteral("USB");
    } else if (const QString mode = hamlibMode(t.mode); !mode.isEmpty()) {
        plan.receiveMode = mode;
        if (f.uplinkHz)
            plan.transmitMode = mode;
    } else if (note && !t.mode.trimmed().isEmpty()) {
        *note = QObject::tr("mode '%1' has no Hamlib name: the radio's mode is left as it is")
                    .arg(input::loggableText(t.mode, 24));
    }
    return plan;
}

std::optional<double> parseFrequency(const QString &text, QString *error)
{
    QString why;
    const std::optional<double> hz = hertzIn(text, &why);
    if (!hz) {
        if (error)
            *error = why;
        return std::nullopt;
    }
    const bool hasUnit = text.contains(QRegularExpression(QStringLiteral("[kKmMgG]")));
    if (!hasUnit && *hz < 1e6 && *hz >= 1) {
        if (error)
            *error = QObject::tr("%1 Hz is below 1 MHz: write the unit (%1M for megahertz)")
                         .arg(input::loggableText(text.trimmed(), 40));
        return std::nullopt;
    }
    const input::NumberRange range{1, kHighestFrequencyHz, " Hz"};
    if (!input::checkNumber(std::round(*hz), range, &why)) {
        if (error)
            *error = why;
        return std::nullopt;
    }
    return std::round(*hz);
}

std::optional<double> parseFrequencyOffset(const QString &text, QString *error)
{
    QString why;
    const std::optional<double> hz = hertzIn(text, &why);
    const input::NumberRange range{-kLargestOffsetHz, kLargestOffsetHz, " Hz"};
    if (!hz || !input::checkNumber(*hz, range, &why)) {
        if (error)
            *error = why;
        return std::nullopt;
    }
    return *hz;
}

std::optional<QString> parseModeName(const QString &text, QString *error)
{
    static const QRegularExpression kMode(QStringLiteral("^[A-Za-z0-9]{1,8}$"));
    const QString t = text.trimmed();
    if (!kMode.match(t).hasMatch()) {
        *error = QObject::tr("'%1' is not a Hamlib mode name (USB, LSB, CW, FM, AM, PKTUSB, ...)")
                     .arg(input::loggableText(text, 24));
        return std::nullopt;
    }
    return t.toUpper();
}

} // namespace slew::radio
