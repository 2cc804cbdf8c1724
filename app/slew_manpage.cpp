// SPDX-License-Identifier: GPL-3.0-or-later
// slew-manpage PROGRAM FILE: writes the manual page of slew or slew-sim,
// made from the same option definitions as their --help. Run by the build;
// not installed.

#include "cli/manpage.h"
#include "cli/slewcommandline.h"

#include <QCoreApplication>
#include <QSaveFile>

#include <cstdio>

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    if (args.size() != 3) {
        std::fprintf(stderr, "usage: slew-manpage slew|slew-sim|slewctl FILE\n");
        return 2;
    }
    const slew::cli::ProgramDescription *program = nullptr;
    if (args[1] == u"slew")
        program = &slew::cli::slewProgram();
    else if (args[1] == u"slew-sim")
        program = &slew::cli::slewSimProgram();
    else if (args[1] == u"slewctl")
        program = &slew::cli::slewctlProgram();
    else {
        std::fprintf(stderr, "slew-manpage: no program '%s'\n", qPrintable(args[1]));
        return 2;
    }
    QSaveFile out(args[2]);
    if (!out.open(QIODevice::WriteOnly)
        || out.write(slew::cli::renderManPage(*program, QStringLiteral(SLEW_VERSION)).toUtf8()) < 0 || !out.commit()) {
        std::fprintf(stderr, "slew-manpage: %s: %s\n", qPrintable(args[2]), qPrintable(out.errorString()));
        return 1;
    }
    return 0;
}
