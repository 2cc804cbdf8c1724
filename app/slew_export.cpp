// SPDX-License-Identifier: GPL-3.0-or-later
// `slew --export-elements`: argument parsing and where the text goes; the
// forms are written by core/sky. The options are described in cli/.

#include "slew_export.h"

#include "cli/argvoptions.h"
#include "cli/elementsetoption.h"
#include "cli/optionnames.h"
#include "cli/slewcommandline.h"
#include "slew_identity.h"

#include "input/atomicfile.h"
#include "input/logtext.h"
#include "sky/elementsetformat.h"

#include <QCommandLineParser>
#include <QCoreApplication>

#include <cstdio>

using namespace slew::sky;
namespace opt = slew::cli::opt;

namespace {

int fail(const QString &message, int status = 2)
{
    std::fprintf(stderr, "slew: %s\n", qPrintable(message));
    return status;
}

} // namespace

bool wantsExportElements(int argc, char **argv)
{
    return slew::cli::argvHasSwitch(argc, argv, opt::exportElements);
}

int runExportElements(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    setUpSlewApplication();
    QCommandLineParser parser;
    slew::cli::describeTo(parser, slew::cli::slewExportElementsMode());
    parser.addPositionalArgument(QStringLiteral("SAT"), QStringLiteral("The satellites to write (default: all)."),
                                 QStringLiteral("[SAT...]"));
    parser.process(app);

    ElementSetForm form = ElementSetForm::Tle;
    if (parser.isSet(opt::format)) {
        const std::optional<ElementSetForm> named = formFromName(parser.value(opt::format));
        if (!named)
            return fail(QStringLiteral("--format: '%1' is not tle, csv, json, xml or kvn")
                            .arg(slew::input::loggableText(parser.value(opt::format), 20)));
        form = *named;
    }
    QString error;
    const auto held = slew::cli::readElementSetOption(parser, slew::cli::commandLineLabel, &error);
    if (!held)
        return fail(error);
    for (const QString &skipped : held->skipped)
        std::fprintf(stderr, "slew: %s\n", qPrintable(skipped));
    std::fprintf(stderr, "slew: element sets from %s\n", qPrintable(held->origin));

    // The satellites named, each exactly once, in the order given; all of
    // them when none is named.
    QList<ElementSet> chosen;
    const QStringList names = parser.positionalArguments();
    for (const QString &name : names) {
        const ElementSet *found = findOneSatellite(held->sets, name, &error);
        if (!found)
            return fail(error, 1);
        chosen.append(*found);
    }
    if (names.isEmpty())
        chosen = held->sets;
    chosen = mergeByCatalogueNumber(chosen);

    const WrittenElementSets written = writeElementSets(chosen, form);
    for (const QString &left : written.left)
        std::fprintf(stderr, "slew: not written as %s: %s\n", qPrintable(formName(form)), qPrintable(left));

    const QString out = parser.value(opt::out);
    if (out.isEmpty() || out == u"-") {
        std::fwrite(written.bytes.constData(), 1, size_t(written.bytes.size()), stdout);
        std::fflush(stdout);
    } else if (const QString why = slew::input::saveAtomically(out, written.bytes); !why.isEmpty()) {
        return fail(QStringLiteral("--out: %1").arg(why));
    }
    std::fprintf(stderr, "slew: %lld of %lld sets written as %s\n", qlonglong(chosen.size() - written.left.size()),
                 qlonglong(chosen.size()), qPrintable(formName(form)));
    return 0;
}
