// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundedfile.h"

#include <QFile>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace slew::input {
namespace {

QString kindOf(mode_t mode)
{
    if (S_ISDIR(mode))
        return QStringLiteral("a directory");
    if (S_ISCHR(mode))
        return QStringLiteral("a character device");
    if (S_ISBLK(mode))
        return QStringLiteral("a block device");
    if (S_ISFIFO(mode))
        return QStringLiteral("a FIFO (named pipe)");
    if (S_ISSOCK(mode))
        return QStringLiteral("a socket");
    return QStringLiteral("not a regular file");
}

QString systemError(int error)
{
    return QString::fromLocal8Bit(std::strerror(error));
}

// Closes the descriptor however the read ends.
struct Descriptor {
    int fd = -1;
    ~Descriptor()
    {
        if (fd >= 0)
            ::close(fd);
    }
};

} // namespace

QString byteSizeText(qint64 bytes)
{
    if (bytes >= 1024 * 1024 && bytes % (1024 * 1024) == 0)
        return QStringLiteral("%1 MiB").arg(bytes / (1024 * 1024));
    if (bytes >= 1024 && bytes % 1024 == 0)
        return QStringLiteral("%1 KiB").arg(bytes / 1024);
    return QStringLiteral("%1 bytes").arg(bytes);
}

// Opens `path` for reading without blocking on a FIFO, and checks that what
// was opened (not the name, which could be swapped meanwhile) is a regular
// file. On failure, result->error says why and the descriptor is closed.
static bool openRegularFile(const QString &path, Descriptor &file, struct stat &info, BoundedRead *result)
{
    if (path.isEmpty()) {
        result->error = QStringLiteral("no file named");
        return false;
    }
    // O_NONBLOCK: opening a FIFO with no writer returns at once instead of
    // waiting for one. O_NOCTTY: a terminal named by mistake does not become
    // the controlling one.
    const QByteArray name = QFile::encodeName(path);
    do {
        file.fd = ::open(name.constData(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    } while (file.fd < 0 && errno == EINTR);
    if (file.fd < 0) {
        result->error = QStringLiteral("%1: %2").arg(path, systemError(errno));
        return false;
    }
    if (::fstat(file.fd, &info) != 0) {
        result->error = QStringLiteral("%1: %2").arg(path, systemError(errno));
        return false;
    }
    if (!S_ISREG(info.st_mode)) {
        result->error = QStringLiteral("%1 is %2, not a file; name a regular file").arg(path, kindOf(info.st_mode));
        return false;
    }
    return true;
}

BoundedRead readBoundedFile(const QString &path, qint64 maxBytes)
{
    BoundedRead result;
    Descriptor file;
    struct stat info {};
    if (!openRegularFile(path, file, info, &result))
        return result;
    const auto tooBig = [&] {
        return QStringLiteral("%1 is over the %2 limit for this file").arg(path, byteSizeText(maxBytes));
    };
    if (info.st_size > maxBytes) {
        result.error = tooBig();
        return result;
    }
    // The size can change while it is read (a file still being written):
    // read until the end, never past one byte over the cap.
    QByteArray bytes;
    bytes.reserve(qsizetype(info.st_size));
    char buffer[64 * 1024];
    for (;;) {
        const qint64 room = maxBytes + 1 - bytes.size();
        const ssize_t n = ::read(file.fd, buffer, size_t(std::min<qint64>(qint64(sizeof buffer), room)));
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            result.error = QStringLiteral("%1: %2").arg(path, systemError(errno));
            return result;
        }
        if (n == 0)
            break;
        bytes.append(buffer, qsizetype(n));
        if (bytes.size() > maxBytes) {
            result.error = tooBig();
            return result;
        }
    }
    result.bytes = bytes;
    return result;
}

BoundedRead readFileHead(const QString &path, qint64 bytes)
{
    BoundedRead result;
    Descriptor file;
    struct stat info {};
    if (!openRegularFile(path, file, info, &result))
        return result;
    QByteArray head(qsizetype(std::max<qint64>(bytes, 0)), '\0');
    qsizetype got = 0;
    while (got < head.size()) {
        const ssize_t n = ::read(file.fd, head.data() + got, size_t(head.size() - got));
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            result.error = QStringLiteral("%1: %2").arg(path, systemError(errno));
            return result;
        }
        if (n == 0)
            break;
        got += qsizetype(n);
    }
    head.truncate(got);
    result.bytes = head;
    return result;
}

} // namespace slew::input
