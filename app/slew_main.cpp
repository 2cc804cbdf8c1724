// SPDX-License-Identifier: GPL-3.0-or-later
// slew: the operator window. Argument parsing and wiring only; everything
// else lives in slewui and slewcore. The options are described in cli/.

#include "slew_identity.h"
#include "cli/argvoptions.h"
#include "cli/optionnames.h"
#include "cli/sharedoptions.h"
#include "cli/slewcommandline.h"
#include "stationwindow.h"
#include "operatortheme.h"
#include "slew_elements.h"
#include "slew_export.h"
#include "slew_headless.h"
#include "slew_schedule.h"
#include "slew_passreport.h"
#include "slew_remote.h"
#include "slew_sky.h"
#include "slew_tune.h"
#include "rotor/rotctldpanel.h"
#include "tracking/timecontroller.h"
#include "transport/hostport.h"
#include "windowsnapshot.h"

#include "rotor/connectionbar.h"
#include "protocol/dialect.h"
#include "bridge/rotctldserver.h"
#include "session/rotatorsession.h"
#include "station/station.h"
#include "sky/site.h"
#include "input/finitenumber.h"
#include "input/logtext.h"
#include "cli/terminationsignalwatcher.h"

#include <QApplication>
#include <QCommandLineParser>

#include <cstdio>
#include <cstring>

namespace opt = slew::cli::opt;

namespace {

struct Arguments {
    QString connectUri;                        // empty: the remembered connection, else the simulator
    std::optional<slew::protocol::Dialect> dialect;
    std::optional<std::pair<double, double>> gotoAzEl;
    QString screenshot;
    int settleMs = 3000;
    std::optional<std::pair<QHostAddress, quint16>> rotctldListen;
    std::optional<int> rotctldMaxClients;
    QString station; // --qth, checked: kept as Sky → Station… keeps it
    // --profile, --limits over it (or over the defaults): the session's
    // profile before it connects.
    std::optional<slew::model::RotatorProfile> profile;
    bool profileFile = false; // --profile: its link and dialect too, unless named
    slew::cli::StationClockOptions clock; // --clock-start, --clock-rate: a rehearsal
    slew::cli::PassRecordOptions passRecords; // --pass-db, --pass-keep-days
};

// Returns an error message, or empty when the arguments are usable.
QString parse(QCommandLineParser &parser, const QStringList &argv, Arguments &out)
{
    slew::cli::describeTo(parser, slew::cli::slewWindowMode());
    parser.process(argv);

    out.connectUri = parser.value(opt::connect);
    if (parser.isSet(opt::dialect)) {
        out.dialect = slew::protocol::dialectFromName(parser.value(opt::dialect));
        if (!out.dialect)
            return QStringLiteral("unknown dialect '%1'").arg(parser.value(opt::dialect));
    }
    if (parser.isSet(opt::gotoAzEl)) {
        // Finite numbers only; the limits gate checks the range when the
        // move is made, against the connected rotator's travel.
        const QStringList parts = parser.value(opt::gotoAzEl).split(QLatin1Char(','));
        const auto az = parts.size() == 2 ? slew::input::finiteNumber(parts[0]) : std::nullopt;
        const auto el = parts.size() == 2 ? slew::input::finiteNumber(parts[1]) : std::nullopt;
        if (!az || !el)
            return QStringLiteral("--goto wants az,el as two numbers (e.g. 210,35), not '%1'")
                .arg(slew::input::loggableText(parser.value(opt::gotoAzEl), 60));
        out.gotoAzEl = std::pair{*az, *el};
    }
    if (parser.isSet(opt::rotctldListen)) {
        QHostAddress address;
        quint16 port = 0;
        if (!slew::transport::parseHostPort(parser.value(opt::rotctldListen), &address, &port))
            return QStringLiteral("--rotctld-listen %1: expected ADDRESS:PORT").arg(parser.value(opt::rotctldListen));
        out.rotctldListen = std::pair{address, port};
    }
    if (parser.isSet(opt::rotctldMaxClients)) {
        out.rotctldMaxClients = parseMaxClients(parser.value(opt::rotctldMaxClients));
        if (!out.rotctldMaxClients)
            return QStringLiteral("--rotctld-max-clients %1: expected a number from 1 to 100000")
                .arg(parser.value(opt::rotctldMaxClients));
    }
    if (parser.isSet(opt::qth)) {
        slew::sky::Site station;
        QString error;
        if (!slew::sky::parseSite(parser.value(opt::qth), &station, &error))
            return QStringLiteral("--qth: %1").arg(error);
        out.station = parser.value(opt::qth).trimmed();
    }
    // As the station service reads them, in the same words.
    QString error;
    if (parser.isSet(opt::profile) || parser.isSet(opt::limits)) {
        slew::model::RotatorProfile profile;
        if (!slew::cli::readProfileOptions(parser, slew::cli::commandLineLabel, &profile, &error))
            return error;
        out.profile = profile;
        out.profileFile = parser.isSet(opt::profile);
    }
    const auto clock = slew::cli::readStationClockOptions(parser, slew::cli::commandLineLabel, &error);
    if (!clock)
        return error;
    out.clock = *clock;
    const auto records = slew::cli::readPassRecordOptions(parser, slew::cli::commandLineLabel, &error);
    if (!records)
        return error;
    out.passRecords = *records;
    out.screenshot = parser.value(opt::screenshot);
    if (parser.isSet(opt::settleMs)) {
        bool ok = false;
        out.settleMs = parser.value(opt::settleMs).toInt(&ok);
        if (!ok || out.settleMs < 0)
            return QStringLiteral("--settle-ms wants a number of milliseconds");
    }
    return {};
}

} // namespace

int main(int argc, char *argv[])
{
    // The station service needs no display, so it branches off before any
    // GUI object exists.
    if (wantsHeadless(argc, argv))
        return runHeadless(argc, argv);
    // So does tuning from the command line.
    if (wantsTune(argc, argv))
        return runTune(argc, argv);
    // And the sky questions: passes, and where things are.
    if (wantsSky(argc, argv))
        return runSky(argc, argv);
    // And the schedule of several targets.
    if (wantsSchedule(argc, argv))
        return runSchedule(argc, argv);
    // And the picture of a recorded pass.
    if (wantsPassReport(argc, argv))
        return runPassReport(argc, argv);
    // And refreshing the element sets into the window's cache.
    if (wantsExportElements(argc, argv))
        return runExportElements(argc, argv);
    if (wantsUpdateElements(argc, argv))
        return runUpdateElements(argc, argv);
    if (wantsUpdateTransponders(argc, argv))
        return runUpdateTransponders(argc, argv);
    // And a station that lives on a broker: no local Station at all.
    if (wantsRemote(argc, argv))
        return runRemote(argc, argv);
    // A screenshot, --help and --version need no display: choose the
    // offscreen platform before the application object picks one.
    bool noDisplay = slew::cli::argvHasOption(argc, argv, opt::screenshot)
                     || slew::cli::argvHasSwitch(argc, argv, opt::help)
                     || slew::cli::argvHasSwitch(argc, argv, opt::version);
    for (int i = 1; i < argc; ++i) // QCommandLineParser's short names for them
        noDisplay = noDisplay || std::strcmp(argv[i], "-h") == 0 || std::strcmp(argv[i], "-v") == 0;
    if (noDisplay && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    setUpSlewApplication();
    slew::ui::applyOperatorTheme(app);

    QCommandLineParser parser;
    Arguments args;
    if (const QString error = parse(parser, app.arguments(), args); !error.isEmpty()) {
        std::fprintf(stderr, "slew: %s\n", qPrintable(error));
        return 2;
    }

    const QString settingsProblem = checkSettingsFile();
    if (!args.station.isEmpty()) {
        // Said kept only when it is: a later --passes would use the old one.
        if (const QString why = slew::model::saveSetting(QLatin1String(slew::sky::kSiteSettingsKey), args.station);
            !why.isEmpty()) {
            std::fprintf(stderr, "slew: --qth: the station was not saved: %s\n", qPrintable(why));
            return 1;
        }
    }

    // The station first: the window is a view of it, and goes first.
    slew::station::Station station;
    slew::session::RotatorSession &session = *station.session();
    // Before the window, whose History tab shows them. A file the station
    // service records into is shown, and this window records nothing.
    const QString recordsProblem =
        station.openPassRecords(args.passRecords.path, args.passRecords.keepDays, /*readWhenTaken=*/true);
    slew::ui::StationWindow window(&station);
    if (args.clock.startJulian)
        window.timeController()->rehearse(*args.clock.startJulian, args.clock.rate);
    window.show();
    if (!settingsProblem.isEmpty())
        window.reportProblem(settingsProblem);
    for (const QString &problem : checkSatelliteNames())
        window.reportProblem(problem);
    if (!recordsProblem.isEmpty())
        window.reportProblem(QStringLiteral("pass records: %1").arg(recordsProblem));

    QString uri = args.connectUri;
    auto dialect = args.dialect;
    if (args.profile)
        session.setProfile(*args.profile);
    if (args.profileFile) {
        // The profile's link and dialect unless named on the command line,
        // as the station service takes them.
        if (uri.isEmpty())
            uri = args.profile->uri;
        if (!dialect)
            dialect = args.profile->dialect;
    }
    if (uri.isEmpty()) {
        uri = slew::ui::ConnectionBar::rememberedUri();
        if (!dialect)
            dialect = slew::ui::ConnectionBar::rememberedDialect();
    }
    if (uri.isEmpty())
        uri = QStringLiteral("sim:");
    if (args.gotoAzEl) {
        QObject::connect(&session, &slew::session::RotatorSession::capabilitiesChanged, &session,
                         [&session, target = *args.gotoAzEl, sent = false](const auto &caps) mutable {
                             if (caps.probed && !sent) {
                                 sent = true;
                                 session.gotoPosition(target.first, target.second);
                             }
                         });
    }
    if (args.rotctldMaxClients)
        station.server()->setMaxClients(*args.rotctldMaxClients);
    window.connectTo(uri, dialect);
    if (args.rotctldListen
        && !window.rotctldPanel()->startListening(args.rotctldListen->first.toString(), args.rotctldListen->second)) {
        std::fprintf(stderr, "slew: the rotctld server could not start; see the Trackers tab\n");
    }
    if (!args.screenshot.isEmpty())
        slew::ui::scheduleWindowSnapshot(&window, args.screenshot, args.settleMs);
    // SIGTERM (a logout, systemd, kill) or SIGINT: as the station service
    // does, stop the rotator and let the stop leave before exiting.
    slew::cli::TerminationSignalWatcher terminationSignals;
    QObject::connect(&terminationSignals, &slew::cli::TerminationSignalWatcher::terminationRequested, &app,
                     [&station](int number) {
                         std::fprintf(stderr, "slew: signal %d: stopping the rotator, then exiting\n", number);
                         // Every rotor stops, no tracker moves one again meanwhile.
                         station.shutdown(QStringLiteral("signal %1").arg(number));
                     });
    QObject::connect(&station, &slew::station::Station::shutDown, &app, &QCoreApplication::quit);
    return app.exec();
}
