// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The settings file (QSettings: ~/.config/Slew/slew.conf), read and written
// so that nothing about it passes silently.
//
// QSettings treats a file it cannot parse as empty and rewrites it at the
// next save, so a damaged file would be lost without a word; and a save
// that cannot reach the disk (a directory or an immutable file in its
// place, a path under a file) only shows in status() after sync(), while
// the process keeps the new value in memory and says nothing. Here a file
// that is not a settings file is moved aside before anything reads it, and
// a save that matters is checked against what the file then holds.

#include <QDateTime>
#include <QString>
#include <QVariant>

class QSettings;

namespace slew::model {

// A settings file bigger than this was not written by Slew.
inline constexpr qint64 kMaxSettingsFileBytes = 16 * 1024 * 1024;

// The file QSettings() uses for this application (its organisation and
// application names, XDG_CONFIG_HOME), worked out without opening it.
QString settingsFilePath();

struct SettingsCheck {
    QString movedTo; // where an unreadable file now is; empty when none was moved
    QString message; // for stderr and the window; empty when all is well
};

// If the file at `path` exists and cannot be read as settings (it is not a
// regular file, is over kMaxSettingsFileBytes, or QSettings reads it with a
// FormatError), it is renamed to `path.broken-YYYYMMDD-HHMMSS` (never
// deleted; -2, -3... if that name is taken) and the message says so, or why
// it could not be moved. A missing file is fine: it is made at first save.
SettingsCheck setAsideUnreadableSettings(const QString &path, const QDateTime &now);
// The same for settingsFilePath(), now: what every entry point runs first.
SettingsCheck setAsideUnreadableSettings();

// Saves `value` under `key` and checks it reached the file: sync() and
// status(), then the file read back from a copy (the process's own
// settings cache would show the new value whatever the disk holds). Empty
// on success, else why, naming the file.
QString saveSetting(QSettings &settings, const QString &key, const QVariant &value);
QString saveSetting(const QString &key, const QVariant &value); // in QSettings()

} // namespace slew::model
