// SPDX-License-Identifier: GPL-3.0-or-later
#include "manpage.h"

#include "optionnames.h"

#include <QStringList>

namespace slew::cli {
namespace {

// Text as roff shows it literally: backslashes and hyphens escaped, and a
// line that would start with a control character made safe.
QString escaped(QString text)
{
    text.replace(u'\\', QStringLiteral("\\e"));
    text.replace(u'-', QStringLiteral("\\-"));
    QStringList lines = text.split(u'\n');
    for (QString &line : lines) {
        if (line.startsWith(u'.') || line.startsWith(u'\''))
            line.prepend(QStringLiteral("\\&"));
    }
    return lines.join(u'\n');
}

QString optionTag(const ProgramOption &option)
{
    QStringList forms;
    for (const QString &name : option.names) {
        QString form = QStringLiteral("\\fB%1\\fR").arg(escaped((name.size() == 1 ? QStringLiteral("-") : QStringLiteral("--")) + name));
        if (!option.valueName.isEmpty())
            form += QStringLiteral(" \\fI%1\\fR").arg(escaped(option.valueName));
        forms << form;
    }
    return forms.join(QStringLiteral(", "));
}

void writeParagraphs(QStringList &out, const QString &text)
{
    for (const QString &paragraph : text.split(QStringLiteral("\n\n"))) {
        if (paragraph.startsWith(QStringLiteral("  "))) {
            out << QStringLiteral(".PP") << QStringLiteral(".RS 4") << QStringLiteral(".nf");
            for (const QString &line : paragraph.split(u'\n'))
                out << escaped(line.mid(2));
            out << QStringLiteral(".fi") << QStringLiteral(".RE");
        } else {
            out << QStringLiteral(".PP") << escaped(paragraph);
        }
    }
}

void writeOptions(QStringList &out, const ProgramMode &mode)
{
    for (const ProgramOption &option : mode.options) {
        out << QStringLiteral(".TP") << optionTag(option) << escaped(option.description);
        if (option.inConfigFile && mode.find(opt::config))
            out << QStringLiteral("May also be set in a \\fB\\-\\-config\\fR file as \\fB%1 =\\fR \\fI%2\\fR.")
                       .arg(escaped(option.longName()), escaped(option.valueName));
    }
    out << QStringLiteral(".TP") << QStringLiteral("\\fB\\-h\\fR, \\fB\\-\\-help\\fR")
        << QStringLiteral("Show the options and exit.") << QStringLiteral(".TP")
        << QStringLiteral("\\fB\\-\\-help\\-all\\fR") << QStringLiteral("Show the options and Qt's own, and exit.")
        << QStringLiteral(".TP")
        << QStringLiteral("\\fB\\-v\\fR, \\fB\\-\\-version\\fR") << QStringLiteral("Show the version and exit.");
}

} // namespace

QString renderManPage(const ProgramDescription &program, const QString &version)
{
    QStringList out;
    out << QStringLiteral(".\\\" Generated from the program's option definitions; edit app/cli, not this file.")
        << QStringLiteral(".TH %1 1 \"\" \"%2 %3\" \"User Commands\"")
               .arg(escaped(program.name.toUpper()), escaped(program.name), escaped(version))
        << QStringLiteral(".SH NAME") << QStringLiteral("%1 \\- %2").arg(escaped(program.name), escaped(program.summary))
        << QStringLiteral(".SH SYNOPSIS");
    for (const ProgramMode &mode : program.modes)
        out << QStringLiteral(".PP") << escaped(mode.synopsis);
    out << QStringLiteral(".SH DESCRIPTION");
    writeParagraphs(out, program.description);

    if (program.modes.size() == 1) {
        out << QStringLiteral(".SH OPTIONS");
        writeOptions(out, program.modes.first());
    } else {
        for (const ProgramMode &mode : program.modes) {
            out << QStringLiteral(".SH \"%1\"").arg(escaped(mode.title.toUpper()));
            writeParagraphs(out, mode.description);
            writeOptions(out, mode);
        }
    }
    for (const ManualSection &section : program.sections) {
        out << QStringLiteral(".SH \"%1\"").arg(escaped(section.heading.toUpper()));
        writeParagraphs(out, section.text);
    }
    return out.join(u'\n') + u'\n';
}

} // namespace slew::cli
