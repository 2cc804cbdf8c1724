// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reading a file that a user named (--tle, --config, --profile, a file://
// element-set source, a cache): only a regular file, and only up to a cap.
//
// QFile::size() is 0 for /dev/zero and a FIFO, so a size check before
// reading lets a device through, and opening a FIFO blocks until a writer
// comes. Here the path is opened without blocking, the open file (not the
// name, which could be swapped meanwhile) is checked to be a regular file,
// and it is read in pieces that stop one byte past the cap. Nothing is read
// from a device, a FIFO, a socket or a directory.

#include <QByteArray>
#include <QString>

namespace slew::input {

struct BoundedRead {
    QByteArray bytes;
    QString error; // empty when the whole file was read

    bool ok() const { return error.isEmpty(); }
};

// The whole of the file at `path`, if it is a regular file of at most
// `maxBytes`; otherwise an error that names the path and says why ("is a
// character device, not a file", "is over the 1 MiB limit ...").
BoundedRead readBoundedFile(const QString &path, qint64 maxBytes);

// The first `bytes` bytes of the regular file at `path` (fewer when the
// file is shorter), opened the same careful way: for a file too large to
// read whole whose kind is told by its first bytes (an SQLite database).
BoundedRead readFileHead(const QString &path, qint64 bytes);

// "64 KiB", "16 MiB": a cap as README and the messages state it.
QString byteSizeText(qint64 bytes);

} // namespace slew::input
