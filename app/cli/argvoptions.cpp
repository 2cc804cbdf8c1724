// SPDX-License-Identifier: GPL-3.0-or-later
#include "argvoptions.h"

#include <QByteArray>

#include <cstring>

namespace slew::cli {
namespace {

// argv's bytes beside an option's name, as the shell passed them: the names
// are plain ASCII, so no decoding is needed to tell them.
QByteArray flag(const QString &longName)
{
    return QByteArrayLiteral("--") + longName.toLatin1();
}

} // namespace

bool argvHasSwitch(int argc, char **argv, const QString &longName)
{
    const QByteArray wanted = flag(longName);
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], wanted.constData()) == 0)
            return true;
    }
    return false;
}

bool argvHasOption(int argc, char **argv, const QString &longName)
{
    const QByteArray wanted = flag(longName);
    const size_t length = size_t(wanted.size());
    for (int i = 1; i < argc; ++i) {
        if (std::strncmp(argv[i], wanted.constData(), length) == 0 && (argv[i][length] == '\0' || argv[i][length] == '='))
            return true;
    }
    return false;
}

} // namespace slew::cli
