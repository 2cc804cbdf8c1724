// SPDX-License-Identifier: GPL-3.0-or-later
#include "passrecordfile.h"

#include "input/boundedfile.h"

#include <QFileInfo>

namespace slew::records {

PassRecordFileKind inspectPassRecordFile(const QString &path, QString *why)
{
    const QFileInfo info(path);
    // A dangling symbolic link is not "absent": SQLite would create its target.
    if (!info.exists() && !info.isSymLink())
        return PassRecordFileKind::Absent;
    const input::BoundedRead head = input::readFileHead(path, sizeof kSqliteHeader);
    if (!head.ok()) {
        *why = head.error;
        return PassRecordFileKind::Unusable;
    }
    if (head.bytes.isEmpty())
        return PassRecordFileKind::Empty;
    if (head.bytes != QByteArray(kSqliteHeader, sizeof kSqliteHeader)) {
        *why = QStringLiteral("%1 is not an SQLite database (it does not start as one); it was left as it is")
                   .arg(path);
        return PassRecordFileKind::Unusable;
    }
    return PassRecordFileKind::Database;
}

} // namespace slew::records
