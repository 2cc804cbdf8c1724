// SPDX-License-Identifier: GPL-3.0-or-later
// `slew --tune URI`: argument parsing and wiring; the work is in core/tuning.
// The options are described in cli/.

#include "slew_identity.h"

#include "input/finitenumber.h"
#include "cli/argvoptions.h"
#include "cli/optionnames.h"
#include "cli/slewcommandline.h"
#include "slew_tune.h"

#include "cli/terminationsignalwatcher.h"
#include "model/rotatorprofile.h"
#include "protocol/dialect.h"
#include "tuning/tuningrun.h"

#include <QCommandLineParser>
#include <QCoreApplication>

#include <cstdio>

namespace opt = slew::cli::opt;

namespace {

int fail(const QString &message)
{
    std::fprintf(stderr, "slew: %s\n", qPrintable(message));
    return 2;
}

void say(const QString &line)
{
    std::fprintf(stdout, "%s\n", qPrintable(line));
    std::fflush(stdout);
}

} // namespace

bool wantsTune(int argc, char **argv)
{
    return slew::cli::argvHasOption(argc, argv, opt::tune);
}

int runTune(int argc, char **argv)
{
    using slew::session::Axis;

    QCoreApplication app(argc, argv);
    setUpSlewApplication();

    QCommandLineParser parser;
    slew::cli::describeTo(parser, slew::cli::slewTuneMode());
    parser.process(app);

    const QString uri = parser.value(opt::tune).trimmed();
    if (uri.isEmpty() || uri.startsWith(QLatin1String("--")))
        return fail(QStringLiteral("--tune needs the rotator's URI, e.g. --tune serial:/dev/ttyUSB0?baud=19200"));
    QList<Axis> axes;
    const QString which = parser.isSet(opt::axis) ? parser.value(opt::axis).toLower() : QStringLiteral("both");
    if (which == u"az" || which == u"azimuth")
        axes = {Axis::Azimuth};
    else if (which == u"el" || which == u"elevation")
        axes = {Axis::Elevation};
    else if (which == u"both")
        axes = {Axis::Azimuth, Axis::Elevation};
    else
        return fail(QStringLiteral("--axis must be az, el or both, not '%1'").arg(parser.value(opt::axis)));
    double stepDegrees = slew::tuning::TuningSettings{}.amplitude;
    if (parser.isSet(opt::step)) {
        QString why;
        const auto value = slew::input::numberIn(parser.value(opt::step), {0.5, 30, "°"}, &why);
        if (!value)
            return fail(QStringLiteral("--step: %1 (0.5 to 30 degrees)").arg(why));
        stepDegrees = *value;
    }

    slew::tuning::TuningRun::Options options;
    if (parser.isSet(opt::profile)) {
        QString error;
        const auto loaded = slew::model::RotatorProfile::load(parser.value(opt::profile), &error);
        if (!loaded)
            return fail(error);
        options.profile = *loaded;
    }
    if (parser.isSet(opt::dialect)) {
        const auto d = slew::protocol::dialectFromName(parser.value(opt::dialect));
        if (!d)
            return fail(QStringLiteral("unknown dialect '%1'").arg(parser.value(opt::dialect)));
        options.profile.dialect = *d;
    }
    options.profile.uri = uri;
    options.axes = axes;
    options.apply = parser.isSet(opt::apply);
    options.stepDegrees = stepDegrees;

    slew::tuning::TuningRun run(options);
    int exitCode = 1;
    QObject::connect(&run, &slew::tuning::TuningRun::output, &app, [](const QString &line) { say(line); });
    QObject::connect(&run, &slew::tuning::TuningRun::problem, &app,
                     [](const QString &line) { std::fprintf(stderr, "slew: %s\n", qPrintable(line)); });
    QObject::connect(&run, &slew::tuning::TuningRun::finished, &app, [&](int code) {
        exitCode = code;
        QCoreApplication::quit();
    });
    // Ctrl-C stops the rotator and puts the old gains back before leaving.
    slew::cli::TerminationSignalWatcher terminations;
    QObject::connect(&terminations, &slew::cli::TerminationSignalWatcher::terminationRequested, &run,
                     &slew::tuning::TuningRun::interrupt);

    say(QStringLiteral("tuning %1 on %2").arg(which, uri));
    run.start();
    app.exec();
    return exitCode;
}
