// SPDX-License-Identifier: GPL-3.0-or-later
// `slew --tune URI`: argument parsing and wiring; the work is in core/tuning.
// The options are described in cli/.

#include "slew_identity.h"
#include "cli/slewcommandline.h"
#include "slew_tune.h"

#include "model/rotatorprofile.h"
#include "protocol/dialect.h"
#include "session/rotatorsession.h"
#include "cli/terminationsignalwatcher.h"
#include "tuning/tuningsequence.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QTimer>

#include <cstdio>
#include <cstring>

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
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--tune") == 0 || std::strncmp(argv[i], "--tune=", 7) == 0)
            return true;
    }
    return false;
}

int runTune(int argc, char **argv)
{
    using slew::session::Axis;
    using slew::session::RotatorSession;

    QCoreApplication app(argc, argv);
    setUpSlewApplication();

    QCommandLineParser parser;
    slew::cli::describeTo(parser, slew::cli::slewTuneMode());
    parser.process(app);
    const QString tune = QStringLiteral("tune"), axis = QStringLiteral("axis"), apply = QStringLiteral("apply"),
                  dialect = QStringLiteral("dialect"), profile = QStringLiteral("profile"),
                  step = QStringLiteral("step");

    const QString uri = parser.value(tune).trimmed();
    if (uri.isEmpty() || uri.startsWith(QLatin1String("--")))
        return fail(QStringLiteral("--tune needs the rotator's URI, e.g. --tune serial:/dev/ttyUSB0?baud=19200"));
    QList<Axis> axes;
    const QString which = parser.isSet(axis) ? parser.value(axis).toLower() : QStringLiteral("both");
    if (which == u"az" || which == u"azimuth")
        axes = {Axis::Azimuth};
    else if (which == u"el" || which == u"elevation")
        axes = {Axis::Elevation};
    else if (which == u"both")
        axes = {Axis::Azimuth, Axis::Elevation};
    else
        return fail(QStringLiteral("--axis must be az, el or both, not '%1'").arg(parser.value(axis)));
    bool stepOk = true;
    const double stepDegrees =
        parser.isSet(step) ? parser.value(step).toDouble(&stepOk) : slew::tuning::TuningSettings{}.amplitude;
    if (!stepOk || !(stepDegrees >= 0.5 && stepDegrees <= 30.0))
        return fail(QStringLiteral("--step must be 0.5 to 30 degrees, not '%1'").arg(parser.value(step)));

    slew::model::RotatorProfile rotator;
    if (parser.isSet(profile)) {
        QString error;
        const auto loaded = slew::model::RotatorProfile::load(parser.value(profile), &error);
        if (!loaded)
            return fail(error);
        rotator = *loaded;
    }
    if (parser.isSet(dialect)) {
        const auto d = slew::protocol::dialectFromName(parser.value(dialect));
        if (!d)
            return fail(QStringLiteral("unknown dialect '%1'").arg(parser.value(dialect)));
        rotator.dialect = *d;
    }
    rotator.uri = uri;
    rotator.pollHz = 50; // a step is measured from the polled positions: poll as often as the session allows

    RotatorSession session;
    session.setProfile(rotator);
    slew::tuning::TuningSequence sequence(&session);
    slew::tuning::TuningSettings settings;
    settings.amplitude = stepDegrees;
    sequence.setSettings(settings);

    int exitCode = 1;
    bool started = false;
    QString lastLine;
    QObject::connect(&sequence, &slew::tuning::TuningSequence::progress, &app,
                     [&](const QString &axisName, int, const QString &what) {
                         const QString line = QStringLiteral("%1: %2").arg(axisName, what);
                         // Step progress repeats with the time; print phases only.
                         if (!what.contains(u':') && line != lastLine)
                             say(line);
                         lastLine = line;
                     });
    QObject::connect(&sequence, &slew::tuning::TuningSequence::finished, &app,
                     [&](const QList<slew::tuning::TuningResult> &results) {
                         say(QString());
                         std::fputs(qPrintable(slew::tuning::formatTuningTable(results)), stdout);
                         for (const auto &r : results) {
                             const int first = slew::tuning::firstGainRegister(r.axis);
                             say(r.applied ? QStringLiteral("%1: new gains kept (CW%2..CW%3, read back)")
                                                 .arg(slew::tuning::axisName(r.axis))
                                                 .arg(first)
                                                 .arg(first + 2)
                                           : QStringLiteral("%1: old gains written back; --apply keeps the new ones")
                                                 .arg(slew::tuning::axisName(r.axis)));
                         }
                         exitCode = 0;
                         session.stop();
                         QTimer::singleShot(100, &app, &QCoreApplication::quit); // let SA SE leave
                     });
    QObject::connect(&sequence, &slew::tuning::TuningSequence::failed, &app, [&](const QString &reason) {
        std::fprintf(stderr, "slew: tuning stopped: %s\n", qPrintable(reason));
        exitCode = 1;
        QTimer::singleShot(100, &app, &QCoreApplication::quit);
    });
    QObject::connect(&session, &RotatorSession::capabilitiesChanged, &app,
                     [&](const slew::session::Capabilities &caps) {
                         if (!caps.probed || started)
                             return;
                         started = true;
                         if (!sequence.start(axes, parser.isSet(apply))) {
                             std::fprintf(stderr, "slew: %s\n", qPrintable(sequence.error()));
                             exitCode = 1;
                             QMetaObject::invokeMethod(&app, &QCoreApplication::quit, Qt::QueuedConnection);
                         }
                     });
    QObject::connect(&session, &RotatorSession::stateChanged, &app,
                     [&](RotatorSession::State state, const QString &detail) {
                         if (state == RotatorSession::State::Disconnected) {
                             std::fprintf(stderr, "slew: %s\n", qPrintable(detail));
                             exitCode = 1;
                             QMetaObject::invokeMethod(&app, &QCoreApplication::quit, Qt::QueuedConnection);
                         }
                     });
    // Ctrl-C stops the rotator and puts the old gains back before leaving.
    slew::cli::TerminationSignalWatcher terminations;
    QObject::connect(&terminations, &slew::cli::TerminationSignalWatcher::terminationRequested, &app, [&] {
        if (!started) {
            QMetaObject::invokeMethod(&app, &QCoreApplication::quit, Qt::QueuedConnection);
            return;
        }
        session.stop();
        sequence.cancel();
    });

    say(QStringLiteral("tuning %1 on %2").arg(which, uri));
    session.connectTo(uri);
    app.exec();
    return exitCode;
}
