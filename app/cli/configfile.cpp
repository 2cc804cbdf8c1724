// SPDX-License-Identifier: GPL-3.0-or-later
#include "configfile.h"

#include <QFile>

namespace slew::cli {
namespace {

// A config file is a few lines; anything much bigger is not one.
constexpr qint64 kLargestFile = 64 * 1024;

QStringList settableNames(const ProgramMode &mode)
{
    QStringList names;
    for (const ProgramOption &option : mode.options) {
        if (option.inConfigFile)
            names << option.longName();
    }
    return names;
}

} // namespace

std::optional<QStringList> parseConfigText(const QString &text, const QString &origin, const ProgramMode &mode,
                                           QString *error)
{
    QStringList arguments;
    const QStringList lines = text.split(u'\n');
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const QString line = lines[i].trimmed();
        if (line.isEmpty() || line.startsWith(u'#'))
            continue;
        const QString where = QStringLiteral("%1:%2").arg(origin).arg(i + 1);
        const qsizetype equals = line.indexOf(u'=');
        if (equals < 0) {
            *error = QStringLiteral("%1: expected `name = value`, got '%2'").arg(where, line.left(80));
            return std::nullopt;
        }
        const QString name = line.left(equals).trimmed();
        const QString value = line.mid(equals + 1).trimmed();
        const ProgramOption *option = mode.find(name);
        if (!option || !option->inConfigFile) {
            *error = QStringLiteral("%1: unknown setting '%2'; a config file may set %3")
                         .arg(where, name.left(80), settableNames(mode).join(QStringLiteral(", ")));
            return std::nullopt;
        }
        if (value.isEmpty())
            continue; // `profile =` in the example: not set
        arguments << QStringLiteral("--%1=%2").arg(name, value);
    }
    return arguments;
}

std::optional<QStringList> readConfigFile(const QString &path, const ProgramMode &mode, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) {
        *error = QStringLiteral("config file %1: %2").arg(path, file.errorString());
        return std::nullopt;
    }
    if (file.size() > kLargestFile) {
        *error = QStringLiteral("config file %1: %2 bytes is too big for a config file").arg(path).arg(file.size());
        return std::nullopt;
    }
    return parseConfigText(QString::fromUtf8(file.readAll()), path, mode, error);
}

std::optional<QStringList> withConfigFile(const QStringList &arguments, const ProgramMode &mode, QString *error)
{
    QString path;
    for (qsizetype i = 1; i < arguments.size(); ++i) {
        const QString &a = arguments[i];
        if (a == u"--config" && i + 1 < arguments.size())
            path = arguments[i + 1];
        else if (a.startsWith(QLatin1String("--config=")))
            path = a.mid(9);
    }
    if (path.isEmpty())
        return arguments;
    auto settings = readConfigFile(path, mode, error);
    if (!settings)
        return std::nullopt;
    QStringList combined{arguments.first()};
    combined << *settings << arguments.mid(1);
    return combined;
}

} // namespace slew::cli
