// SPDX-License-Identifier: GPL-3.0-or-later
#include "configfile.h"

#include "optionnames.h"

#include "input/boundedfile.h"
#include "input/logtext.h"

namespace slew::cli {
namespace {

QStringList settableNames(const ProgramMode &mode)
{
    QStringList names;
    for (const ProgramOption &option : mode.options) {
        if (option.inConfigFile)
            names << option.longName();
    }
    return names;
}

// Text from the file as a message may show it: no control characters (an
// ESC sequence would reach the terminal or the journal), and short.
QString shown(const QString &text)
{
    return input::loggableText(text, 80);
}

// Whether the command line itself gives the option (then it wins, and the
// file's line is not where the value came from).
bool givenOnCommandLine(const QStringList &arguments, const QString &name)
{
    const QString plain = QStringLiteral("--") + name;
    for (qsizetype i = 1; i < arguments.size(); ++i) {
        if (arguments[i] == plain || arguments[i].startsWith(plain + u'='))
            return true;
    }
    return false;
}

} // namespace

QString ConfiguredArguments::label(const QString &longName) const
{
    const auto it = origins.constFind(longName);
    if (it == origins.cend())
        return QStringLiteral("--") + longName;
    return QStringLiteral("%1: %2").arg(*it, longName);
}

std::optional<ConfiguredArguments> parseConfigText(const QString &text, const QString &origin,
                                                   const ProgramMode &mode, QString *error)
{
    ConfiguredArguments result;
    QHash<QString, qsizetype> firstLine;
    const QStringList lines = text.split(u'\n');
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const QString line = lines[i].trimmed();
        if (line.isEmpty() || line.startsWith(u'#'))
            continue;
        const QString where = QStringLiteral("%1:%2").arg(origin).arg(i + 1);
        const qsizetype equals = line.indexOf(u'=');
        if (equals < 0) {
            *error = QStringLiteral("%1: expected `name = value`, got '%2'").arg(where, shown(line));
            return std::nullopt;
        }
        const QString name = line.left(equals).trimmed();
        const QString value = line.mid(equals + 1).trimmed();
        const ProgramOption *option = mode.find(name);
        if (!option || !option->inConfigFile) {
            *error = QStringLiteral("%1: unknown setting '%2'; a config file may set %3")
                         .arg(where, shown(name), settableNames(mode).join(QStringLiteral(", ")));
            return std::nullopt;
        }
        // A name given twice is a mistake either way round: which one the
        // user meant cannot be told, so neither is taken silently.
        if (const auto seen = firstLine.constFind(name); seen != firstLine.cend() && !option->repeatable) {
            *error = QStringLiteral("%1: '%2' is set again; it was set on line %3 already: keep one")
                         .arg(where, name)
                         .arg(*seen + 1);
            return std::nullopt;
        }
        if (!firstLine.contains(name))
            firstLine.insert(name, i);
        if (value.isEmpty())
            continue; // `profile =` in the example: not set
        if (option->valueName.isEmpty()) {
            // A switch: `radio-restore = true`.
            const QString answer = value.toLower();
            if (answer != u"true" && answer != u"false" && answer != u"yes" && answer != u"no") {
                *error = QStringLiteral("%1: %2 is a switch: true or false, not '%3'").arg(where, name, shown(value));
                return std::nullopt;
            }
            if (answer == u"true" || answer == u"yes") {
                result.arguments << QStringLiteral("--%1").arg(name);
                result.origins.insert(name, where);
            }
            continue;
        }
        result.arguments << QStringLiteral("--%1=%2").arg(name, value);
        result.origins.insert(name, where);
    }
    return result;
}

std::optional<ConfiguredArguments> readConfigFile(const QString &path, const ProgramMode &mode, QString *error)
{
    const input::BoundedRead read = input::readBoundedFile(path, kLargestConfigFile);
    if (!read.ok()) {
        *error = QStringLiteral("config file %1").arg(read.error);
        return std::nullopt;
    }
    return parseConfigText(QString::fromUtf8(read.bytes), path, mode, error);
}

std::optional<ConfiguredArguments> withConfigFile(const QStringList &arguments, const ProgramMode &mode,
                                                  QString *error)
{
    const QString flag = QStringLiteral("--") + opt::config;
    QString path;
    for (qsizetype i = 1; i < arguments.size(); ++i) {
        const QString &a = arguments[i];
        if (a == flag && i + 1 < arguments.size())
            path = arguments[i + 1];
        else if (a.startsWith(flag + u'='))
            path = a.mid(flag.size() + 1);
    }
    if (path.isEmpty())
        return ConfiguredArguments{arguments, {}};
    auto settings = readConfigFile(path, mode, error);
    if (!settings)
        return std::nullopt;
    ConfiguredArguments combined;
    combined.arguments << arguments.first();
    for (const QString &setting : std::as_const(settings->arguments)) {
        // A repeatable option given on the command line replaces the file's
        // (a single one wins by coming last).
        const QString name = setting.mid(2).section(u'=', 0, 0);
        const ProgramOption *option = mode.find(name);
        if (option && option->repeatable && givenOnCommandLine(arguments, name))
            continue;
        combined.arguments << setting;
    }
    combined.arguments << arguments.mid(1);
    for (auto it = settings->origins.cbegin(); it != settings->origins.cend(); ++it) {
        if (!givenOnCommandLine(arguments, it.key()))
            combined.origins.insert(it.key(), it.value());
    }
    return combined;
}

} // namespace slew::cli
