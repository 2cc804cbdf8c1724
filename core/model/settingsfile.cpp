// SPDX-License-Identifier: GPL-3.0-or-later
#include "settingsfile.h"

#include "input/boundedfile.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>
#include <QStringDecoder>
#include <QTemporaryDir>

#include <optional>

namespace slew::model {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("SettingsFile", text);
}

// The settings in `bytes`, read by QSettings from a file of their own: a
// path no QSettings in this process has used, so none of its cache.
struct Copy {
    QSettings::Status status = QSettings::AccessError;
    QVariant value;
};

Copy readCopy(const QByteArray &bytes, const QString &key)
{
    QTemporaryDir dir;
    QFile file(dir.filePath(QStringLiteral("copy.conf")));
    if (!dir.isValid() || !file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size())
        return {};
    file.close();
    QSettings settings(file.fileName(), QSettings::IniFormat);
    return {settings.status(), key.isEmpty() ? QVariant() : settings.value(key)};
}

// Whether `bytes` have the shape of an INI file as QSettings writes one:
// UTF-8 text without control characters, each line blank, a comment, a
// [section] or a key=value. QSettings' own reader is lenient (random bytes
// read as a few odd keys, with no FormatError) and would drop whatever it
// could not read at the next save.
bool looksLikeSettingsText(const QByteArray &bytes)
{
    QStringDecoder utf8(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
    const QString text = utf8.decode(bytes);
    if (utf8.hasError())
        return false;
    for (const QChar c : text) {
        const char16_t u = c.unicode();
        if ((u < 0x20 && u != u'\t' && u != u'\n' && u != u'\r') || u == 0x7f)
            return false;
    }
    for (const QStringView line : QStringView(text).split(u'\n')) {
        const QStringView t = line.trimmed();
        if (t.isEmpty() || t.startsWith(u';') || t.startsWith(u'#') || t.contains(u'='))
            continue;
        if (t.startsWith(u'[') && t.endsWith(u']'))
            continue;
        return false;
    }
    return true;
}

// Why the file at `path` is no settings file, or nothing.
std::optional<QString> unreadable(const QString &path)
{
    if (!QFileInfo(path).isFile())
        return tr("%1 is not a regular file").arg(path);
    const input::BoundedRead read = input::readBoundedFile(path, kMaxSettingsFileBytes);
    if (!read.ok())
        return read.error;
    if (!looksLikeSettingsText(read.bytes) || readCopy(read.bytes, {}).status == QSettings::FormatError)
        return tr("%1 is not in the settings format").arg(path);
    return std::nullopt;
}

QString asideName(const QString &path, const QDateTime &now)
{
    const QString base = path + QStringLiteral(".broken-") + now.toString(QStringLiteral("yyyyMMdd-HHmmss"));
    QString name = base;
    for (int n = 2; QFileInfo(name).exists() || QFileInfo(name).isSymLink(); ++n)
        name = base + QLatin1Char('-') + QString::number(n);
    return name;
}

// An INI file gives strings back: a number saved comes back as its text.
bool sameValue(const QVariant &read, const QVariant &saved)
{
    if (saved.typeId() == QMetaType::QStringList)
        return read.toStringList() == saved.toStringList();
    return read.isValid() && read.toString() == saved.toString();
}

} // namespace

QString settingsFilePath()
{
    // As QSettings makes it on Unix: the generic config location (which
    // follows XDG_CONFIG_HOME), then organisation/application.conf.
    const QString organisation = QCoreApplication::organizationName().isEmpty()
                                     ? QStringLiteral("Unknown Organization")
                                     : QCoreApplication::organizationName();
    return QStandardPaths::writableLocation(QStandardPaths::GenericConfigLocation) + QLatin1Char('/') + organisation
           + QLatin1Char('/') + QCoreApplication::applicationName() + QStringLiteral(".conf");
}

SettingsCheck setAsideUnreadableSettings(const QString &path, const QDateTime &now)
{
    const QFileInfo info(path);
    if (!info.exists() && !info.isSymLink())
        return {}; // made at the first save
    const std::optional<QString> why = unreadable(path);
    if (!why)
        return {};
    const QString aside = asideName(path, now);
    if (!QDir().rename(path, aside)) {
        return {{},
                tr("the settings file cannot be read (%1), and it could not be moved aside to %2: "
                   "settings will not be kept until it is fixed or removed")
                    .arg(*why, aside)};
    }
    return {aside, tr("the settings file cannot be read (%1); it was moved aside to %2, "
                      "and Slew starts with default settings")
                       .arg(*why, aside)};
}

SettingsCheck setAsideUnreadableSettings()
{
    return setAsideUnreadableSettings(settingsFilePath(), QDateTime::currentDateTime());
}

QString saveSetting(QSettings &settings, const QString &key, const QVariant &value)
{
    const QString path = settings.fileName();
    settings.setValue(key, value);
    settings.sync();
    switch (settings.status()) {
    case QSettings::NoError:
        break;
    case QSettings::AccessError:
        return tr("the settings file %1 cannot be written").arg(path);
    case QSettings::FormatError:
        return tr("the settings file %1 is not in the settings format, so it is not overwritten").arg(path);
    }
    // QSettings may say NoError and still not have written (a root process
    // past permissions, a file replaced meanwhile): what counts is the file.
    const input::BoundedRead read = input::readBoundedFile(path, kMaxSettingsFileBytes);
    if (!read.ok())
        return tr("the settings file cannot be read back after saving: %1").arg(read.error);
    if (!sameValue(readCopy(read.bytes, key).value, value))
        return tr("the settings file %1 does not hold the new value after saving").arg(path);
    return {};
}

QString saveSetting(const QString &key, const QVariant &value)
{
    QSettings settings;
    return saveSetting(settings, key, value);
}

} // namespace slew::model
