// SPDX-License-Identifier: GPL-3.0-or-later
#include "brokerpassword.h"

#include "input/boundedfile.h"

#include <QFileInfo>

namespace slew::remote {

std::optional<QString> readPasswordFile(const QString &path, QString *error)
{
    const input::BoundedRead read = input::readBoundedFile(path, kLargestPasswordFile);
    if (!read.ok()) {
        *error = QStringLiteral("password file %1").arg(read.error);
        return std::nullopt;
    }
    if (QFileInfo(path).permissions() & QFileDevice::ReadOther) {
        *error = QStringLiteral("password file %1 can be read by every user of this machine: chmod o-r %1 (or 600)")
                     .arg(path);
        return std::nullopt;
    }
    QByteArray line = read.bytes;
    if (const qsizetype end = line.indexOf('\n'); end >= 0)
        line.truncate(end);
    if (line.endsWith('\r'))
        line.chop(1);
    if (line.isEmpty()) {
        *error = QStringLiteral("password file %1 is empty: the password is its first line").arg(path);
        return std::nullopt;
    }
    for (const char c : line) {
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
            *error = QStringLiteral("password file %1: the first line has a control character in it").arg(path);
            return std::nullopt;
        }
    }
    return QString::fromUtf8(line);
}

std::optional<QString> brokerPassword(const QString &file, QString *error)
{
    if (!file.isEmpty())
        return readPasswordFile(file, error);
    return qEnvironmentVariable(kPasswordVariable);
}

} // namespace slew::remote
