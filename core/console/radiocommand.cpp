// SPDX-License-Identifier: GPL-3.0-or-later
#include "radiocommand.h"

#include "input/logtext.h"
#include "radio/radioplan.h"

#include <QObject>

namespace slew::console {

std::optional<RadioCommand> parseRadioCommand(const QStringList &words, QString *error)
{
    RadioCommand command;
    if (words.isEmpty())
        return command;
    const QString verb = words.first().toLower();
    const QStringList arguments = words.mid(1);
    auto wants = [&](qsizetype n, const char *usage) {
        if (arguments.size() == n)
            return true;
        *error = QObject::tr("usage: %1").arg(QLatin1String(usage));
        return false;
    };
    if (verb == u"freq" || verb == u"tx") {
        const bool transmit = verb == u"tx";
        if (arguments.isEmpty() && !transmit)
            return command; // read
        if (!wants(1, transmit ? "tx FREQ" : "freq [FREQ]"))
            return std::nullopt;
        const std::optional<double> hz = radio::parseFrequency(arguments.first(), error);
        if (!hz)
            return std::nullopt;
        command.kind = transmit ? RadioCommand::Kind::SetTransmit : RadioCommand::Kind::SetReceive;
        command.hz = *hz;
        return command;
    }
    if (verb == u"split") {
        if (!wants(1, "split on|off"))
            return std::nullopt;
        const QString state = arguments.first().toLower();
        if (state != u"on" && state != u"off") {
            *error = QObject::tr("usage: split on|off");
            return std::nullopt;
        }
        command.kind = RadioCommand::Kind::Split;
        command.on = state == u"on";
        return command;
    }
    if (verb == u"mode" || verb == u"txmode") {
        if (!wants(1, verb == u"mode" ? "mode MODE" : "txmode MODE"))
            return std::nullopt;
        const std::optional<QString> mode = radio::parseModeName(arguments.first(), error);
        if (!mode)
            return std::nullopt;
        command.kind = verb == u"mode" ? RadioCommand::Kind::Mode : RadioCommand::Kind::TransmitMode;
        command.mode = *mode;
        return command;
    }
    *error = QObject::tr("unknown radio command '%1' (freq, tx, split, mode, txmode)")
                 .arg(input::loggableText(words.first(), 40));
    return std::nullopt;
}

QString radioCommandSummary()
{
    return QStringLiteral("freq              the receive (and, with split on, transmit) frequency\n"
                          "freq FREQ         tune the receive frequency (145.8M, 435.125 MHz, hertz)\n"
                          "tx FREQ           tune the transmit frequency (the split VFO)\n"
                          "split on|off      transmit on VFOB, receive on VFOA; or not\n"
                          "mode MODE         the receive mode (USB, LSB, CW, FM, AM, PKTUSB, ...)\n"
                          "txmode MODE       the transmit mode, with split on\n");
}

} // namespace slew::console
