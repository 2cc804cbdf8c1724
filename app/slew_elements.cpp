// SPDX-License-Identifier: GPL-3.0-or-later
// `slew --update-elements`: argument parsing and one line per source; the
// downloading, checking and caching are in core/sky. The options are
// described in cli/.

#include "slew_elements.h"

#include "cli/argvoptions.h"
#include "cli/optionnames.h"
#include "cli/slewcommandline.h"
#include "slew_identity.h"

#include "radio/transpondersources.h"
#include "sky/elementsetsources.h"
#include "station/station.h"
#include "input/logtext.h"

#include <QCommandLineParser>
#include <QCoreApplication>

#include <cstdio>

using namespace slew::sky;
namespace opt = slew::cli::opt;

namespace {

int refuse(const QString &message)
{
    std::fprintf(stderr, "slew: %s\n", qPrintable(message));
    return 2;
}

// The URLs named on the command line, as the window's dialog takes them.
bool readUrls(const QStringList &texts, QList<QUrl> *urls, QString *error)
{
    for (const QString &text : texts) {
        const std::optional<QUrl> url = slew::sky::elementSetUrl(text);
        if (!url) {
            *error = QStringLiteral("%1 is not an http, https or file URL").arg(slew::input::loggableText(text, 80));
            return false;
        }
        if (!urls->contains(*url))
            urls->append(*url);
    }
    return true;
}

} // namespace

bool wantsUpdateElements(int argc, char **argv)
{
    return slew::cli::argvHasSwitch(argc, argv, opt::updateElements);
}

int runUpdateElements(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    setUpSlewApplication();
    QCommandLineParser parser;
    slew::cli::describeTo(parser, slew::cli::slewUpdateElementsMode());
    parser.addPositionalArgument(QStringLiteral("URL"), QStringLiteral("The sources to refresh."),
                                 QStringLiteral("[URL...]"));
    parser.process(app);

    QList<QUrl> urls;
    QString error;
    if (!readUrls(parser.positionalArguments(), &urls, &error))
        return refuse(error);
    QList<QUrl> saved = savedElementSetUrls();
    if (urls.isEmpty())
        urls = saved;
    if (urls.isEmpty())
        return refuse(QStringLiteral("no sources: name URLs (such as %1), or list them in the window "
                                     "(Sky → Element sets…)")
                          .arg(QLatin1String(kExampleElementSetUrl)));
    // The URLs named join the window's sources, so the window, --where,
    // --passes and --schedule read what was just fetched.
    bool added = false;
    for (const QUrl &url : std::as_const(urls)) {
        if (!saved.contains(url)) {
            saved.append(url);
            added = true;
        }
    }
    if (added)
        saveElementSetUrls(saved);

    // The station's element sets: the same cache the window and the service read.
    slew::station::Station station;
    ElementSetSources &sources = *station.elementSets();
    sources.setUrls(urls);
    int status = 0;
    QObject::connect(&sources, &ElementSetSources::finished, &app, [&sources, &status] {
        QStringList failed;
        for (const ElementSetSourceStatus &s : sources.status()) {
            std::fprintf(stdout, "%s\n", qPrintable(describeSource(s)));
            if (sourceFailed(s))
                failed << s.url.toString();
        }
        std::fflush(stdout);
        if (!failed.isEmpty()) {
            std::fprintf(stderr, "slew: %lld of %lld sources not refreshed: %s\n", qlonglong(failed.size()),
                         qlonglong(sources.status().size()), qPrintable(failed.join(QStringLiteral(", "))));
            status = 1;
        }
        QCoreApplication::exit(status);
    });
    sources.refresh();
    app.exec();
    return status;
}

bool wantsUpdateTransponders(int argc, char **argv)
{
    return slew::cli::argvHasSwitch(argc, argv, opt::updateTransponders);
}

int runUpdateTransponders(int argc, char **argv)
{
    using namespace slew::radio;
    QCoreApplication app(argc, argv);
    setUpSlewApplication();
    QCommandLineParser parser;
    slew::cli::describeTo(parser, slew::cli::slewUpdateTranspondersMode());
    parser.addPositionalArgument(QStringLiteral("URL"), QStringLiteral("The sources to refresh and keep."),
                                 QStringLiteral("[URL...]"));
    parser.process(app);

    QList<QUrl> urls;
    QString error;
    if (!readUrls(parser.positionalArguments(), &urls, &error))
        return refuse(error);
    if (urls.isEmpty())
        urls = savedTransponderUrls();
    if (urls.isEmpty())
        urls = {QUrl(QString::fromLatin1(kSatnogsTransmittersUrl))};
    // Kept, so the window and `slew --headless --radio` read the same cache.
    saveTransponderUrls(urls);

    slew::station::Station station;
    TransponderSources &sources = *station.transponders();
    sources.setUrls(urls);
    int status = 0;
    QObject::connect(&sources, &TransponderSources::finished, &app, [&sources, &status] {
        QStringList failed;
        for (const TransponderSourceStatus &s : sources.status()) {
            std::fprintf(stdout, "%s\n", qPrintable(describeTransponderSource(s)));
            if (!s.fetched || !s.error.isEmpty())
                failed << s.url.toString();
        }
        std::fflush(stdout);
        if (!failed.isEmpty()) {
            std::fprintf(stderr, "slew: %lld of %lld sources not refreshed: %s\n", qlonglong(failed.size()),
                         qlonglong(sources.status().size()), qPrintable(failed.join(QStringLiteral(", "))));
            status = 1;
        }
        QCoreApplication::exit(status);
    });
    sources.refresh();
    app.exec();
    return status;
}
