// SPDX-License-Identifier: GPL-3.0-or-later
#include "consolecommand.h"

#include "input/finitenumber.h"

#include <cmath>

namespace slew::console {
namespace {

// The controller's configuration registers (CR/CW) that exist: 1..13.
constexpr int kFirstRegister = 1;
constexpr int kLastRegister = 13;
constexpr double kShortestWatch = 0.05;
constexpr double kLongestWatch = 3600;

std::optional<double> number(const QString &word)
{
    return input::finiteNumber(word);
}

std::optional<int> registerNumber(const QString &word, QString *error)
{
    QString digits = word;
    if (digits.startsWith(QLatin1String("CR"), Qt::CaseInsensitive) || digits.startsWith(QLatin1String("CW"), Qt::CaseInsensitive))
        digits = digits.mid(2);
    bool ok = false;
    const int reg = digits.toInt(&ok);
    if (!ok || reg < kFirstRegister || reg > kLastRegister) {
        *error = QStringLiteral("config: register must be %1 to %2, not '%3'").arg(kFirstRegister).arg(kLastRegister).arg(word.left(20));
        return std::nullopt;
    }
    return reg;
}

bool expectWords(const QStringList &words, qsizetype count, const QString &usage, QString *error)
{
    if (words.size() == count)
        return true;
    *error = QStringLiteral("usage: %1").arg(usage);
    return false;
}

} // namespace

std::optional<ConsoleCommand> parseConsoleCommand(const QStringList &given, QString *error)
{
    using Kind = ConsoleCommand::Kind;
    if (given.isEmpty()) {
        *error = QStringLiteral("no command; try 'help'");
        return std::nullopt;
    }
    // --wait may stand anywhere after the command word.
    QStringList words = given;
    const bool wait = words.removeAll(QStringLiteral("--wait")) > 0;
    const QString name = words.first().toLower();
    ConsoleCommand c;
    c.wait = wait;
    if (wait && name != u"goto" && name != u"park" && name != u"home") {
        *error = QStringLiteral("--wait goes with goto, park and home");
        return std::nullopt;
    }

    if (name == u"get" || name == u"stop" || name == u"park" || name == u"home" || name == u"help" || name == u"quit"
        || name == u"exit") {
        if (!expectWords(words, 1, name, error))
            return std::nullopt;
        c.kind = name == u"get" ? Kind::Get : name == u"stop" ? Kind::Stop : name == u"park" ? Kind::Park
               : name == u"home" ? Kind::Home : name == u"help" ? Kind::Help : Kind::Quit;
        return c;
    }
    if (name == u"goto") {
        if (!expectWords(words, 3, QStringLiteral("goto AZ EL [--wait]"), error))
            return std::nullopt;
        const auto az = number(words[1]), el = number(words[2]);
        if (!az || !el) {
            *error = QStringLiteral("goto: '%1 %2' are not two numbers of degrees").arg(words[1].left(20), words[2].left(20));
            return std::nullopt;
        }
        c.kind = Kind::Goto;
        c.azimuth = *az;
        c.elevation = *el;
        return c;
    }
    if (name == u"watch") {
        // watch, watch 0.5, watch --interval 0.5, watch --interval=0.5
        QString value = QStringLiteral("1");
        if (words.size() == 2)
            value = words[1].startsWith(QLatin1String("--interval=")) ? words[1].mid(11) : words[1];
        else if (words.size() == 3 && words[1] == u"--interval")
            value = words[2];
        else if (words.size() != 1) {
            *error = QStringLiteral("usage: watch [--interval SECONDS]");
            return std::nullopt;
        }
        const auto seconds = number(value);
        if (!seconds || *seconds < kShortestWatch || *seconds > kLongestWatch) {
            *error = QStringLiteral("watch: the interval is %1 to %2 seconds, not '%3'")
                         .arg(kShortestWatch).arg(kLongestWatch).arg(value.left(20));
            return std::nullopt;
        }
        c.kind = Kind::Watch;
        c.intervalSeconds = *seconds;
        return c;
    }
    if (name == u"raw") {
        if (words.size() < 2) {
            *error = QStringLiteral("usage: raw 'LINE'");
            return std::nullopt;
        }
        c.kind = Kind::Raw;
        c.text = words.mid(1).join(u' ');
        return c;
    }
    if (name == u"config") {
        const QString verb = words.value(1).toLower();
        if (verb == u"get" && expectWords(words, 3, QStringLiteral("config get REG"), error)) {
            const auto reg = registerNumber(words[2], error);
            if (!reg)
                return std::nullopt;
            c.kind = Kind::ConfigGet;
            c.reg = *reg;
            return c;
        }
        if (verb == u"set" && expectWords(words, 4, QStringLiteral("config set REG VALUE"), error)) {
            const auto reg = registerNumber(words[2], error);
            if (!reg)
                return std::nullopt;
            c.kind = Kind::ConfigSet;
            c.reg = *reg;
            c.text = words[3];
            return c;
        }
        if (verb != u"get" && verb != u"set")
            *error = QStringLiteral("usage: config get REG | config set REG VALUE");
        return std::nullopt;
    }
    *error = QStringLiteral("unknown command '%1'; try 'help'").arg(words.first().left(20));
    return std::nullopt;
}

QStringList splitConsoleLine(const QString &line)
{
    QStringList words;
    QString word;
    QChar quote;
    bool inWord = false;
    for (const QChar ch : line) {
        if (!quote.isNull()) {
            if (ch == quote)
                quote = QChar();
            else
                word += ch;
        } else if (ch == u'\'' || ch == u'"') {
            quote = ch;
            inWord = true;
        } else if (ch.isSpace()) {
            if (inWord)
                words << word;
            word.clear();
            inWord = false;
        } else {
            word += ch;
            inWord = true;
        }
    }
    if (inWord)
        words << word;
    return words;
}

QString consoleCommandSummary()
{
    return QStringLiteral(
        "get                       print the position\n"
        "goto AZ EL [--wait]       move; with --wait, return once there\n"
        "stop                      stop both axes\n"
        "park [--wait]             go to the park position\n"
        "home [--wait]             find the end stops and zero\n"
        "watch [--interval S]      print the position every S seconds until Ctrl-C\n"
        "raw 'LINE'                send one line as it is (limit-checked) and print the answer\n"
        "config get REG            read a configuration register (CR1..CR13)\n"
        "config set REG VALUE      write a register (CW) and read it back\n"
        "help, quit                at the prompt\n");
}

} // namespace slew::console
