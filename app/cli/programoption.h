// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A program's command line described once, as data: the options of each way
// of running it (the window, --headless, --tune, slew-sim), what each mode is
// for, and what a reader of the manual needs besides. --help, the station's
// config file and the man pages are all made from these descriptions, so
// they cannot drift apart.

#include <QCommandLineOption>
#include <QList>
#include <QString>
#include <QStringList>

namespace slew::cli {

struct ProgramOption {
    QStringList names;       // the first is the long name, without dashes
    QString valueName;       // empty: a switch that takes no value
    QString description;     // one sentence or two; shown in --help and the manual
    bool inConfigFile = false; // may also be given as `name = value` in a --config file
    // May be given more than once (`--track A --track B`; in a config file,
    // a line each). Given on the command line, it replaces the file's.
    bool repeatable = false;

    QCommandLineOption toQt() const;
    QString longName() const { return names.first(); }
};

// One way of running a program: `slew --headless …` is a mode of slew.
struct ProgramMode {
    QString title;           // "Station service"; a section heading in the manual
    QString synopsis;        // the usage line, program name first
    QString description;     // what the mode does, for --help and the manual
    QList<ProgramOption> options;

    const ProgramOption *find(QStringView longName) const;
};

// A section of the manual after OPTIONS: FILES, EXAMPLES, SEE ALSO…
// Paragraphs are separated by blank lines; a paragraph whose first line
// starts with two spaces is shown verbatim (commands and file listings).
struct ManualSection {
    QString heading;
    QString text;
};

struct ProgramDescription {
    QString name;            // "slew"
    QString summary;         // the NAME line after the dash
    QString description;     // the DESCRIPTION paragraphs
    QList<ProgramMode> modes;
    QList<ManualSection> sections;
};

} // namespace slew::cli
