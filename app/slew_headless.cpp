// SPDX-License-Identifier: GPL-3.0-or-later
// `slew --headless --connect URI --rotctld-listen ADDR:PORT`: argument parsing
// and wiring for the station service; the work is in core/station. The
// options are described in cli/.

#include "slew_identity.h"
#include "cli/argvoptions.h"
#include "cli/configfile.h"
#include "cli/elementsetoption.h"
#include "cli/optionnames.h"
#include "cli/sharedoptions.h"
#include "cli/trackoptions.h"
#include "cli/slewcommandline.h"
#include "transport/hostport.h"
#include "slew_headless.h"

#include "station/radiooptions.h"
#include "session/connectionplan.h"
#include "station/remoteoperation.h"
#include "remote/brokeraddress.h"
#include "remote/brokerpassword.h"
#include "station/stationservice.h"
#include "bridge/rotctldserver.h"
#include "protocol/dialect.h"
#include "transport/linkfactory.h"
#include "cli/terminationsignalwatcher.h"
#include "sky/elementage.h"
#include "sky/elementsetformat.h"
#include "sky/utctime.h"

#include "input/finitenumber.h"
#include "input/logtext.h"

#include <QCommandLineParser>
#include <QCoreApplication>

#include <cstdio>
#include <functional>

namespace opt = slew::cli::opt;

namespace {

int fail(const QString &message)
{
    std::fprintf(stderr, "slew: %s\n", qPrintable(message));
    return 2;
}

using slew::cli::OptionLabel;

QString shown(const QString &text)
{
    return slew::cli::shownValue(text);
}

// --track and what goes with it: the targets (cli/trackoptions.h), --min-el,
// --guard, --max-element-age, --clock-start, --clock-rate. Messages name each option as `label`
// gives it.
std::optional<slew::station::ServiceConfig::Track> readTrack(const QCommandLineParser &parser,
                                                              const OptionLabel &label, QString *error)
{
    slew::station::ServiceConfig::Track track;
    const auto targets = slew::cli::readTrackTargets(parser, label, error);
    if (!targets)
        return std::nullopt;
    track.targets = *targets;
    QString why;
    if (parser.isSet(opt::minEl)) {
        const auto value = slew::input::numberIn(parser.value(opt::minEl), {-5, 90, "°"}, &why);
        if (!value) {
            *error = QStringLiteral("%1: %2 (degrees from -5 to 90)").arg(label(opt::minEl), why);
            return std::nullopt;
        }
        track.minElevationDeg = *value;
    }
    if (parser.isSet(opt::guard)) {
        if (track.targets.size() < 2) {
            *error = QStringLiteral("%1 goes with a schedule: --track given more than once").arg(label(opt::guard));
            return std::nullopt;
        }
        const auto value = slew::input::numberIn(parser.value(opt::guard), {0, 3600, " s"}, &why);
        if (!value) {
            *error = QStringLiteral("%1: %2 (seconds between two passes, 0 to 3600)").arg(label(opt::guard), why);
            return std::nullopt;
        }
        track.guardSeconds = *value;
    }
    if (parser.isSet(opt::maxElementAge)) {
        const auto value = slew::input::numberIn(
            parser.value(opt::maxElementAge), {slew::sky::kLeastElementAgeLimitDays, slew::sky::kMostElementAgeLimitDays, " days"}, &why);
        if (!value) {
            *error = QStringLiteral("%1: %2 (days from the elements' epoch)").arg(label(opt::maxElementAge), why);
            return std::nullopt;
        }
        track.maxElementAgeDays = *value;
    }
    const auto clock = slew::cli::readStationClockOptions(parser, label, error);
    if (!clock)
        return std::nullopt;
    track.clockStartJulian = clock->startJulian;
    track.clockRate = clock->rate;
    return track;
}

// --radio and what goes with it. Messages name each option as `label` gives it.
std::optional<slew::station::RadioOptions> readRadio(const QCommandLineParser &parser, const OptionLabel &label,
                                                     QString *error)
{
    using namespace slew::station;
    RadioOptions radio;
    radio.uri = parser.value(opt::radio).trimmed();
    QString why;
    // Each option's value through its parser; false with the message made.
    auto read = [&](const QString &option, auto parse, auto assign) {
        if (!parser.isSet(option))
            return true;
        const auto value = parse(parser.value(option), &why);
        if (!value) {
            *error = QStringLiteral("%1: %2").arg(label(option), why);
            return false;
        }
        assign(*value);
        return true;
    };
    if (!read(opt::downlink, slew::radio::parseFrequency, [&](double hz) { radio.downlinkHz = hz; })
        || !read(opt::uplink, slew::radio::parseFrequency, [&](double hz) { radio.uplinkHz = hz; })
        || !read(opt::downlinkOffset, slew::radio::parseFrequencyOffset, [&](double hz) { radio.downlinkOffsetHz = hz; })
        || !read(opt::uplinkOffset, slew::radio::parseFrequencyOffset, [&](double hz) { radio.uplinkOffsetHz = hz; })
        || !read(opt::downlinkMode, slew::radio::parseModeName, [&](const QString &m) { radio.downlinkMode = m; })
        || !read(opt::uplinkMode, slew::radio::parseModeName, [&](const QString &m) { radio.uplinkMode = m; })
        || !read(opt::doppler, parseDopplerOn, [&](slew::radio::DopplerOn on) { radio.correct = on; })
        || !read(opt::radioVfos, parseVfoLayout, [&](slew::radio::VfoLayout l) { radio.vfos = l; })
        || !read(opt::uplinkFollows, parseUplinkFollows, [&](slew::radio::UplinkFollowsDial f) { radio.uplinkFollows = f; }))
        return std::nullopt;
    if (parser.isSet(opt::transponderInvert)) {
        if (radio.uplinkFollows && *radio.uplinkFollows != slew::radio::UplinkFollowsDial::OppositeWay) {
            *error = QStringLiteral("%1 and --uplink-follows say different things")
                         .arg(label(opt::transponderInvert));
            return std::nullopt;
        }
        radio.uplinkFollows = slew::radio::UplinkFollowsDial::OppositeWay;
    }
    radio.restoreAfterPass = parser.isSet(opt::radioRestore);
    radio.transponderFiles = parser.values(opt::transponders);
    radio.transponderName = parser.value(opt::transponder);
    const bool byHand = radio.downlinkHz || radio.uplinkHz;
    if (byHand && !radio.transponderFiles.isEmpty()) {
        *error = QStringLiteral("%1 and --downlink/--uplink: give the frequencies one way").arg(label(opt::transponders));
        return std::nullopt;
    }
    if (radio.uplinkHz && !radio.downlinkHz) {
        *error = QStringLiteral("%1 needs --downlink too").arg(label(opt::uplink));
        return std::nullopt;
    }
    if (parser.isSet(opt::transponder) && radio.transponderFiles.isEmpty()) {
        *error = QStringLiteral("%1 goes with --transponders").arg(label(opt::transponder));
        return std::nullopt;
    }
    return radio;
}

// --mqtt and what goes with it: the broker, the station's name on it, the
// password (from a file or the environment, never the command line), and
// the satellites a remote `track` may name (--tle).
std::optional<slew::station::RemoteOptions> readRemote(const QCommandLineParser &parser, const OptionLabel &label,
                                                       QString *error)
{
    slew::station::RemoteOptions remote;
    QString why;
    const auto broker = slew::remote::parseBrokerAddress(parser.value(opt::mqtt), &why);
    if (!broker) {
        *error = QStringLiteral("%1: %2").arg(label(opt::mqtt), why);
        return std::nullopt;
    }
    if (!broker->stationName.isEmpty()) {
        *error = QStringLiteral("%1: the station's name goes in --station-name, not in the broker's address")
                     .arg(label(opt::mqtt));
        return std::nullopt;
    }
    remote.broker = *broker;
    if (!parser.isSet(opt::stationName)) {
        *error = QStringLiteral("%1 needs --station-name NAME: the station's topic level on the broker").arg(label(opt::mqtt));
        return std::nullopt;
    }
    remote.stationName = parser.value(opt::stationName).trimmed();
    if (const QString bad = slew::remote::checkStationName(remote.stationName); !bad.isEmpty()) {
        *error = QStringLiteral("%1: %2").arg(label(opt::stationName), bad);
        return std::nullopt;
    }
    const auto password = slew::remote::brokerPassword(parser.value(opt::mqttPasswordFile), &why);
    if (!password) {
        *error = QStringLiteral("%1: %2").arg(label(opt::mqttPasswordFile), why);
        return std::nullopt;
    }
    remote.password = *password;
    // The satellites a remote `track` may name: --tle's, else the cached
    // copies of the window's sources (none is no error: a remote may still
    // ask for the sun, the moon or a fixed point).
    if (parser.isSet(opt::tle)) {
        const auto sets = slew::cli::readElementSetOption(parser, label, error);
        if (!sets)
            return std::nullopt;
        remote.elementSets = sets->sets;
    } else {
        remote.elementSets = slew::cli::cachedElementSets().sets;
    }
    return remote;
}

// The radio's options, each of which goes with --radio.
QStringList radioOptions()
{
    return {opt::downlink,      opt::uplink,        opt::downlinkMode,      opt::uplinkMode,
            opt::doppler,       opt::uplinkFollows, opt::downlinkOffset,    opt::uplinkOffset,
            opt::transponders,  opt::transponder,   opt::transponderInvert, opt::radioRestore,
            opt::radioVfos};
}

} // namespace

std::optional<int> parseMaxClients(const QString &text)
{
    bool ok = false;
    const int n = text.toInt(&ok);
    if (!ok || n < 1 || n > 100000)
        return std::nullopt;
    return n;
}

bool wantsHeadless(int argc, char *argv[])
{
    return slew::cli::argvHasSwitch(argc, argv, opt::headless);
}

int runHeadless(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    setUpSlewApplication();

    // A --config file stands for options written before the real ones.
    QString error;
    const auto configured = slew::cli::withConfigFile(app.arguments(), slew::cli::slewHeadlessMode(), &error);
    if (!configured)
        return fail(error);
    // How a message names an option: its file and line when the config
    // file gave it, else --name.
    const auto label = [&](const QString &name) { return configured->label(name); };
    QCommandLineParser parser;
    slew::cli::describeTo(parser, slew::cli::slewHeadlessMode());
    parser.process(configured->arguments);
    checkSettingsFile(); // saved calibrations are read from them
    checkSatelliteNames();

    slew::station::ServiceConfig config;
    if (!slew::cli::readProfileOptions(parser, label, &config.profile, &error))
        return fail(error);
    if (parser.isSet(opt::connect))
        config.profile.uri = parser.value(opt::connect);
    if (parser.isSet(opt::dialect)) {
        const auto d = slew::protocol::dialectFromName(parser.value(opt::dialect));
        if (!d)
            return fail(QStringLiteral("%1: unknown dialect '%2'").arg(label(opt::dialect), shown(parser.value(opt::dialect))));
        config.profile.dialect = *d;
    }
    // Where neither names one, the link may (`dialect=`, a simulator's own),
    // as the window's connection bar takes it; and its `firmware=`.
    config.profile = slew::session::commandLineConnectionProfile(config.profile, parser.isSet(opt::dialect) || parser.isSet(opt::profile));
    if (parser.isSet(opt::rotctldListen)) {
        if (!slew::transport::parseHostPort(parser.value(opt::rotctldListen), &config.rotctldAddress, &config.rotctldPort))
            return fail(QStringLiteral("%1 %2: expected ADDRESS:PORT, with a port from 0 to 65535")
                            .arg(label(opt::rotctldListen), shown(parser.value(opt::rotctldListen))));
        config.rotctldEnabled = true;
    }
    if (parser.isSet(opt::rotctldAllow)) {
        for (const QString &a : parser.value(opt::rotctldAllow).split(u',', Qt::SkipEmptyParts)) {
            const QHostAddress address(a.trimmed());
            if (address.isNull())
                return fail(QStringLiteral("%1: '%2' is not an address").arg(label(opt::rotctldAllow), shown(a)));
            config.allowedClients.append(address);
        }
    }

    if (parser.isSet(opt::rotctldMaxClients)) {
        const auto n = parseMaxClients(parser.value(opt::rotctldMaxClients));
        if (!n)
            return fail(QStringLiteral("%1 %2: expected a number from 1 to 100000")
                            .arg(label(opt::rotctldMaxClients), shown(parser.value(opt::rotctldMaxClients))));
        config.rotctldMaxClients = *n;
    }

    if (parser.isSet(opt::rotors)) {
        const QString list = parser.value(opt::rotors);
        const auto rotors = slew::station::parseRotorList(list, &error);
        if (!rotors)
            return fail(QStringLiteral("%1 %2: %3").arg(label(opt::rotors), shown(list), error));
        config.rotors = *rotors;
    }

    if (parser.isSet(opt::qth)) {
        slew::sky::Site where;
        if (!slew::sky::parseSite(parser.value(opt::qth), &where, &error))
            return fail(QStringLiteral("%1: %2").arg(label(opt::qth), error));
        if (!slew::cli::readHorizonOption(parser, label, &where.horizon, &error))
            return fail(error);
        config.station = where;
    } else if (parser.isSet(opt::horizon)) {
        return fail(QStringLiteral("%1 goes with --qth: the horizon is the station's").arg(label(opt::horizon)));
    }

    if (parser.isSet(opt::track)) {
        auto track = readTrack(parser, label, &error);
        if (!track)
            return fail(error);
        if (!config.station)
            return fail(QStringLiteral("--track needs --qth: where the antenna stands"));
        config.track = *track;
    } else {
        for (const QString &option : {opt::tle, opt::minEl, opt::guard, opt::maxElementAge, opt::clockStart, opt::clockRate}) {
            // With --mqtt, --tle names the satellites a remote `track` may ask for.
            if (parser.isSet(option) && !(option == opt::tle && parser.isSet(opt::mqtt)))
                return fail(QStringLiteral("%1 goes with --track%2")
                                .arg(label(option), option == opt::tle ? QStringLiteral(" or --mqtt") : QString()));
        }
    }

    if (parser.isSet(opt::radio)) {
        if (!config.track || config.track->target().kind != slew::tracking::TrackTarget::Kind::Satellite)
            return fail(QStringLiteral("%1 goes with --track of a satellite: Doppler is a satellite's")
                            .arg(label(opt::radio)));
        if (config.track->targets.size() > 1)
            return fail(QStringLiteral("%1 goes with one --track: the radio's frequencies are one satellite's (a "
                                       "schedule of several tunes no radio yet)")
                            .arg(label(opt::radio)));
        auto radio = readRadio(parser, label, &error);
        if (!radio)
            return fail(error);
        config.radio = *radio;
    } else {
        for (const QString &option : radioOptions()) {
            if (parser.isSet(option))
                return fail(QStringLiteral("%1 goes with --radio").arg(label(option)));
        }
    }

    const auto records = slew::cli::readPassRecordOptions(parser, label, &error);
    if (!records)
        return fail(error);
    config.passRecords = records->path;
    config.passKeepDays = records->keepDays;
    if (parser.isSet(opt::mqtt)) {
        auto remote = readRemote(parser, label, &error);
        if (!remote)
            return fail(error);
        config.remote = *remote;
    } else {
        for (const QString &option : {opt::stationName, opt::mqttPasswordFile}) {
            if (parser.isSet(option))
                return fail(QStringLiteral("%1 goes with --mqtt").arg(label(option)));
        }
    }

    slew::station::StationService station;
    if (!station.start(config, &error))
        return fail(error);

    slew::cli::TerminationSignalWatcher terminationSignals;
    QObject::connect(&terminationSignals, &slew::cli::TerminationSignalWatcher::terminationRequested, &station,
                     [&station](int number) { station.shutdown(QStringLiteral("signal %1").arg(number)); });
    QObject::connect(&station, &slew::station::StationService::finished, &app, &QCoreApplication::quit);
    return app.exec();
}
