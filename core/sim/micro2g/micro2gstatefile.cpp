// SPDX-License-Identifier: GPL-3.0-or-later
#include "micro2gstatefile.h"

#include "micro2gcontroller.h"

#include <QFile>
#include <QJsonDocument>
#include <QSaveFile>

namespace slew::sim {

QString loadMicro2gState(const QString &path, Micro2gController &controller)
{
    QFile file(path);
    if (!file.exists())
        return {};
    if (!file.open(QIODevice::ReadOnly))
        return QStringLiteral("%1: %2").arg(path, file.errorString());
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(file.readAll(), &parseError);
    if (!doc.isObject())
        return QStringLiteral("%1: not a Micro-2g state file (%2)").arg(path, parseError.errorString());
    if (const QString e = controller.restoreSettings(doc.object()); !e.isEmpty())
        return QStringLiteral("%1: %2").arg(path, e);
    return {};
}

QString saveMicro2gState(const QString &path, const Micro2gController &controller)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return QStringLiteral("%1: %2").arg(path, file.errorString());
    file.write(QJsonDocument(controller.settings()).toJson());
    if (!file.commit())
        return QStringLiteral("%1: %2").arg(path, file.errorString());
    return {};
}

} // namespace slew::sim
