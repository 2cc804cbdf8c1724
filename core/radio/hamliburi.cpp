// SPDX-License-Identifier: GPL-3.0-or-later
#include "hamliburi.h"

#include "hamliblibrary.h"
#include "input/finitenumber.h"
#include "input/logtext.h"

#include <QObject>
#include <QSet>
#include <QUrlQuery>

#include <algorithm>
#include <array>

namespace slew::radio {

namespace {

// The rates Hamlib 4.5.4 sets on a serial line (serial_setup); any other
// it refuses only when the port is opened.
constexpr std::array kSerialRates{300, 600, 1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200, 230400};

// Hamlib copies the device's name into a buffer of 512 bytes.
constexpr qsizetype kMaxDeviceBytes = 511;

// CI-V addresses of radios; 0x00 is everyone's and 0xE0 up the controllers'.
constexpr int kMinCivAddress = 0x01;
constexpr int kMaxCivAddress = 0xDF;

std::optional<HamlibRadioConfig> refuse(QString *why, const QString &text)
{
    if (why)
        *why = text;
    return std::nullopt;
}

QString knownRates()
{
    QStringList rates;
    for (const int rate : kSerialRates)
        rates << QString::number(rate);
    return rates.join(QLatin1String(", "));
}

// A device is a path: Hamlib takes a name without a slash for host:port
// and would open a network connection instead.
bool isDevicePath(const QString &device, QString *why)
{
    if (!device.startsWith(u'/')) {
        *why = QObject::tr("device '%1' is not a path (expected device=/dev/ttyUSB0)")
                   .arg(input::loggableText(device, 60));
        return false;
    }
    if (device.toLocal8Bit().size() > kMaxDeviceBytes) {
        *why = QObject::tr("device path longer than %1 bytes").arg(kMaxDeviceBytes);
        return false;
    }
    if (std::any_of(device.begin(), device.end(), [](QChar c) { return c.unicode() < 0x20 || c.unicode() == 0x7f; })) {
        *why = QObject::tr("device '%1' has control characters").arg(input::loggableText(device, 60));
        return false;
    }
    return true;
}

std::optional<int> civAddress(const QString &value)
{
    bool ok = false;
    const int address = value.startsWith(QLatin1String("0x"), Qt::CaseInsensitive) ? value.mid(2).toInt(&ok, 16)
                                                                                     : value.toInt(&ok, 10);
    if (!ok || address < kMinCivAddress || address > kMaxCivAddress)
        return std::nullopt;
    return address;
}

std::optional<HamlibRadioConfig> simConfig(const QUrl &url, QString *why)
{
    if (!url.path().isEmpty() || url.hasQuery() || url.hasFragment() || !url.host().isEmpty())
        return refuse(why, QObject::tr("the built-in radio takes no path or options (expected sim:)"));
    const std::optional<HamlibModel> dummy = hamlibModel(kHamlibDummyModel);
    if (!dummy)
        return refuse(why, QObject::tr("this Hamlib has no dummy rig (model %1)").arg(kHamlibDummyModel));
    HamlibRadioConfig config;
    config.uri = QStringLiteral("sim:");
    config.model = dummy->number;
    config.modelName = dummy->name;
    return config;
}

} // namespace

std::optional<HamlibRadioConfig> hamlibRadioConfig(const QUrl &url, const QString &uri, QString *why)
{
    if (url.scheme().compare(QLatin1String("sim"), Qt::CaseInsensitive) == 0)
        return simConfig(url, why);

    const QString expected = QObject::tr("expected hamlib:MODEL?device=/dev/ttyUSB0");
    if (!url.host().isEmpty() || url.hasFragment())
        return refuse(why, QObject::tr("not a Hamlib radio (%1)").arg(expected));
    const QString number = url.path();
    if (number.isEmpty())
        return refuse(why, QObject::tr("no Hamlib model number (%1; rigctl -l lists the models)").arg(expected));
    const std::optional<int> modelNumber = input::wholeNumber(number);
    if (!modelNumber || *modelNumber <= 0 || number.trimmed() != number)
        return refuse(why, QObject::tr("'%1' is not a Hamlib model number (%2)")
                               .arg(input::loggableText(number, 40), expected));
    const std::optional<HamlibModel> model = hamlibModel(*modelNumber);
    if (!model)
        return refuse(why, QObject::tr("Hamlib knows no radio model %1 (rigctl -l lists them)").arg(*modelNumber));

    HamlibRadioConfig config;
    config.uri = uri;
    config.model = model->number;
    config.modelName = model->name;
    QSet<QString> seen;
    for (const auto &[key, value] : QUrlQuery(url).queryItems(QUrl::FullyDecoded)) {
        if (seen.contains(key))
            return refuse(why, QObject::tr("option '%1' given twice").arg(input::loggableText(key, 20)));
        seen.insert(key);
        QString problem;
        if (key == QLatin1String("device")) {
            if (!model->serial)
                return refuse(why, QObject::tr("the %1 has no serial line: device= is for serial radios").arg(model->name));
            if (!isDevicePath(value, &problem))
                return refuse(why, problem);
            config.device = value;
        } else if (key == QLatin1String("baud")) {
            if (!model->serial)
                return refuse(why, QObject::tr("the %1 has no serial line: baud= is for serial radios").arg(model->name));
            const std::optional<int> baud = input::wholeNumber(value);
            if (!baud || std::find(kSerialRates.begin(), kSerialRates.end(), *baud) == kSerialRates.end())
                return refuse(why, QObject::tr("baud rate '%1' is not one of %2")
                                       .arg(input::loggableText(value, 20), knownRates()));
            config.baud = *baud;
        } else if (key == QLatin1String("civaddr")) {
            if (!model->hasCivAddress)
                return refuse(why, QObject::tr("the %1 takes no CI-V address").arg(model->name));
            const std::optional<int> address = civAddress(value);
            if (!address)
                return refuse(why, QObject::tr("CI-V address '%1' is not one from 0x01 to 0xDF")
                                       .arg(input::loggableText(value, 20)));
            config.civAddress = *address;
        } else {
            return refuse(why, QObject::tr("unknown hamlib option '%1' (known: device, baud, civaddr)")
                                   .arg(input::loggableText(key, 20)));
        }
    }
    if (model->serial && config.device.isEmpty())
        return refuse(why, QObject::tr("the %1 is on a serial line: name it (hamlib:%2?device=/dev/ttyUSB0)")
                               .arg(model->name)
                               .arg(model->number));
    return config;
}

} // namespace slew::radio
