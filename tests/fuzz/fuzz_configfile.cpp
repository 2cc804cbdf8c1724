// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzz target: the station service's config-file reader.
//
// Input: a config file's bytes. The mode is a small one of its own (the
// reader takes any), with settable options, one that is not, and a switch.
// Checked besides crashes and sanitizer reports: a refusal names the file
// and a line of it and carries no control character (the text reaches a
// terminal and the journal); an accepted file gives only settable options,
// each once, each with the line it came from.
//
// Built with libFuzzer when SLEW_FUZZ is on (packaging/dev.sh fuzz); the
// normal build replays the seed corpus through it (corpusreplay.cpp).

#include "cli/configfile.h"

#include <QSet>

#include <cstdint>
#include <cstdio>
#include <cstdlib>

using namespace slew::cli;

namespace {

[[noreturn]] void fail(const char *what)
{
    std::fprintf(stderr, "fuzz_configfile: %s\n", what);
    std::abort();
}

const ProgramMode &mode()
{
    static const ProgramMode m = [] {
        ProgramMode mode;
        mode.options = {
            {{QStringLiteral("connect")}, QStringLiteral("URI"), QStringLiteral("link"), true},
            {{QStringLiteral("rotctld-listen")}, QStringLiteral("address:port"), QStringLiteral("server"), true},
            {{QStringLiteral("qth")}, QStringLiteral("station"), QStringLiteral("station"), true},
            {{QStringLiteral("profile")}, QStringLiteral("file"), QStringLiteral("profile"), true},
            {{QStringLiteral("clock-start")}, QStringLiteral("time"), QStringLiteral("not in files"), false},
            {{QStringLiteral("headless")}, {}, QStringLiteral("a switch"), false},
        };
        return mode;
    }();
    return m;
}

bool hasControlCharacter(const QString &text)
{
    for (const QChar c : text) {
        const char16_t u = c.unicode();
        if (u < 0x20 || (u >= 0x7f && u < 0xa0))
            return true;
    }
    return false;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size > std::size_t(kLargestConfigFile))
        return 0; // the reader refuses such a file before parsing it
    const QString text = QString::fromUtf8(reinterpret_cast<const char *>(data), qsizetype(size));
    const QString origin = QStringLiteral("f.conf");
    QString error;
    const auto read = parseConfigText(text, origin, mode(), &error);
    if (!read) {
        if (!error.startsWith(origin + u':'))
            fail("a refusal that does not name the file");
        const qsizetype lines = text.count(u'\n') + 1;
        const int line = error.section(u':', 1, 1).toInt();
        if (line < 1 || line > lines)
            fail("a refusal that names no line of the file");
        if (hasControlCharacter(error))
            fail("a refusal that echoes a control character");
        return 0;
    }
    QSet<QString> seen;
    for (const QString &argument : read->arguments) {
        const QString name = argument.mid(2).section(u'=', 0, 0);
        const ProgramOption *option = mode().find(name);
        if (!argument.startsWith(QLatin1String("--")) || !option || !option->inConfigFile)
            fail("an argument for an option a file may not set");
        if (seen.contains(name))
            fail("an option given twice");
        seen.insert(name);
        if (!read->origins.value(name).startsWith(origin + u':'))
            fail("a setting without the line it came from");
    }
    return 0;
}
