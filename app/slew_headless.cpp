// SPDX-License-Identifier: GPL-3.0-or-later
// `slew --headless --connect URI --rotctld-listen ADDR:PORT`: argument parsing
// and wiring for the station service; the work is in core/station. The
// options are described in cli/.

#include "slew_identity.h"
#include "cli/configfile.h"
#include "cli/elementsetoption.h"
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
#include <cstring>
#include <functional>
#include <string_view>

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
    const QString minEl = QStringLiteral("min-el");
    if (parser.isSet(minEl)) {
        const auto value = slew::input::numberIn(parser.value(minEl), {-5, 90, "°"}, &why);
        if (!value) {
            *error = QStringLiteral("%1: %2 (degrees from -5 to 90)").arg(label(minEl), why);
            return std::nullopt;
        }
        track.minElevationDeg = *value;
    }
    const QString guard = QStringLiteral("guard");
    if (parser.isSet(guard)) {
        if (track.targets.size() < 2) {
            *error = QStringLiteral("%1 goes with a schedule: --track given more than once").arg(label(guard));
            return std::nullopt;
        }
        const auto value = slew::input::numberIn(parser.value(guard), {0, 3600, " s"}, &why);
        if (!value) {
            *error = QStringLiteral("%1: %2 (seconds between two passes, 0 to 3600)").arg(label(guard), why);
            return std::nullopt;
        }
        track.guardSeconds = *value;
    }
    const QString maxAge = QStringLiteral("max-element-age");
    if (parser.isSet(maxAge)) {
        const auto value = slew::input::numberIn(
            parser.value(maxAge), {slew::sky::kLeastElementAgeLimitDays, slew::sky::kMostElementAgeLimitDays, " days"}, &why);
        if (!value) {
            *error = QStringLiteral("%1: %2 (days from the elements' epoch)").arg(label(maxAge), why);
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
    radio.uri = parser.value(QStringLiteral("radio")).trimmed();
    QString why;
    // Each option's value through its parser; false with the message made.
    auto read = [&](const char *name, auto parse, auto assign) {
        const QString option = QString::fromLatin1(name);
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
    if (!read("downlink", slew::radio::parseFrequency, [&](double hz) { radio.downlinkHz = hz; })
        || !read("uplink", slew::radio::parseFrequency, [&](double hz) { radio.uplinkHz = hz; })
        || !read("downlink-offset", slew::radio::parseFrequencyOffset, [&](double hz) { radio.downlinkOffsetHz = hz; })
        || !read("uplink-offset", slew::radio::parseFrequencyOffset, [&](double hz) { radio.uplinkOffsetHz = hz; })
        || !read("downlink-mode", slew::radio::parseModeName, [&](const QString &m) { radio.downlinkMode = m; })
        || !read("uplink-mode", slew::radio::parseModeName, [&](const QString &m) { radio.uplinkMode = m; })
        || !read("doppler", parseDopplerOn, [&](slew::radio::DopplerOn on) { radio.correct = on; })
        || !read("radio-vfos", parseVfoLayout, [&](slew::radio::VfoLayout l) { radio.vfos = l; })
        || !read("uplink-follows", parseUplinkFollows, [&](slew::radio::UplinkFollowsDial f) { radio.uplinkFollows = f; }))
        return std::nullopt;
    if (parser.isSet(QStringLiteral("transponder-invert"))) {
        if (radio.uplinkFollows && *radio.uplinkFollows != slew::radio::UplinkFollowsDial::OppositeWay) {
            *error = QStringLiteral("%1 and --uplink-follows say different things")
                         .arg(label(QStringLiteral("transponder-invert")));
            return std::nullopt;
        }
        radio.uplinkFollows = slew::radio::UplinkFollowsDial::OppositeWay;
    }
    radio.restoreAfterPass = parser.isSet(QStringLiteral("radio-restore"));
    radio.transponderFiles = parser.values(QStringLiteral("transponders"));
    radio.transponderName = parser.value(QStringLiteral("transponder"));
    const QString transponders = QStringLiteral("transponders");
    const bool byHand = radio.downlinkHz || radio.uplinkHz;
    if (byHand && !radio.transponderFiles.isEmpty()) {
        *error = QStringLiteral("%1 and --downlink/--uplink: give the frequencies one way").arg(label(transponders));
        return std::nullopt;
    }
    if (radio.uplinkHz && !radio.downlinkHz) {
        *error = QStringLiteral("%1 needs --downlink too").arg(label(QStringLiteral("uplink")));
        return std::nullopt;
    }
    if (parser.isSet(QStringLiteral("transponder")) && radio.transponderFiles.isEmpty()) {
        *error = QStringLiteral("%1 goes with --transponders").arg(label(QStringLiteral("transponder")));
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
    const QString mqtt = QStringLiteral("mqtt"), name = QStringLiteral("station-name"),
                  passwordFile = QStringLiteral("mqtt-password-file"), tle = QStringLiteral("tle");
    slew::station::RemoteOptions remote;
    QString why;
    const auto broker = slew::remote::parseBrokerAddress(parser.value(mqtt), &why);
    if (!broker) {
        *error = QStringLiteral("%1: %2").arg(label(mqtt), why);
        return std::nullopt;
    }
    if (!broker->stationName.isEmpty()) {
        *error = QStringLiteral("%1: the station's name goes in --station-name, not in the broker's address")
                     .arg(label(mqtt));
        return std::nullopt;
    }
    remote.broker = *broker;
    if (!parser.isSet(name)) {
        *error = QStringLiteral("%1 needs --station-name NAME: the station's topic level on the broker").arg(label(mqtt));
        return std::nullopt;
    }
    remote.stationName = parser.value(name).trimmed();
    if (const QString bad = slew::remote::checkStationName(remote.stationName); !bad.isEmpty()) {
        *error = QStringLiteral("%1: %2").arg(label(name), bad);
        return std::nullopt;
    }
    const auto password = slew::remote::brokerPassword(parser.value(passwordFile), &why);
    if (!password) {
        *error = QStringLiteral("%1: %2").arg(label(passwordFile), why);
        return std::nullopt;
    }
    remote.password = *password;
    // The satellites a remote `track` may name: --tle's, else the cached
    // copies of the window's sources (none is no error: a remote may still
    // ask for the sun, the moon or a fixed point).
    if (parser.isSet(tle)) {
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
const char *const kRadioOptions[] = {"downlink",        "uplink",         "downlink-mode", "uplink-mode",
                                     "doppler",         "uplink-follows", "downlink-offset", "uplink-offset",
                                     "transponders",    "transponder",    "transponder-invert", "radio-restore",
                                     "radio-vfos"};

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
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--headless") == 0)
            return true;
    }
    return false;
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
    const QString connect = QStringLiteral("connect"), dialect = QStringLiteral("dialect"),
                  profile = QStringLiteral("profile"), listen = QStringLiteral("rotctld-listen"),
                  allow = QStringLiteral("rotctld-allow"), maxClients = QStringLiteral("rotctld-max-clients");

    slew::station::ServiceConfig config;
    if (!slew::cli::readProfileOptions(parser, label, &config.profile, &error))
        return fail(error);
    if (parser.isSet(connect))
        config.profile.uri = parser.value(connect);
    if (parser.isSet(dialect)) {
        const auto d = slew::protocol::dialectFromName(parser.value(dialect));
        if (!d)
            return fail(QStringLiteral("%1: unknown dialect '%2'").arg(label(dialect), shown(parser.value(dialect))));
        config.profile.dialect = *d;
    }
    // Where neither names one, the link may (`dialect=`, a simulator's own),
    // as the window's connection bar takes it; and its `firmware=`.
    config.profile = slew::session::commandLineConnectionProfile(config.profile, parser.isSet(dialect) || parser.isSet(profile));
    if (parser.isSet(listen)) {
        if (!slew::transport::parseHostPort(parser.value(listen), &config.rotctldAddress, &config.rotctldPort))
            return fail(QStringLiteral("%1 %2: expected ADDRESS:PORT, with a port from 0 to 65535")
                            .arg(label(listen), shown(parser.value(listen))));
        config.rotctldEnabled = true;
    }
    if (parser.isSet(allow)) {
        for (const QString &a : parser.value(allow).split(u',', Qt::SkipEmptyParts)) {
            const QHostAddress address(a.trimmed());
            if (address.isNull())
                return fail(QStringLiteral("%1: '%2' is not an address").arg(label(allow), shown(a)));
            config.allowedClients.append(address);
        }
    }

    if (parser.isSet(maxClients)) {
        const auto n = parseMaxClients(parser.value(maxClients));
        if (!n)
            return fail(QStringLiteral("%1 %2: expected a number from 1 to 100000")
                            .arg(label(maxClients), shown(parser.value(maxClients))));
        config.rotctldMaxClients = *n;
    }

    if (parser.isSet(QStringLiteral("rotors"))) {
        const QString list = parser.value(QStringLiteral("rotors"));
        const auto rotors = slew::station::parseRotorList(list, &error);
        if (!rotors)
            return fail(QStringLiteral("%1 %2: %3").arg(label(QStringLiteral("rotors")), shown(list), error));
        config.rotors = *rotors;
    }

    if (parser.isSet(QStringLiteral("qth"))) {
        slew::sky::Site where;
        if (!slew::sky::parseSite(parser.value(QStringLiteral("qth")), &where, &error))
            return fail(QStringLiteral("%1: %2").arg(label(QStringLiteral("qth")), error));
        if (!slew::cli::readHorizonOption(parser, label, &where.horizon, &error))
            return fail(error);
        config.station = where;
    } else if (parser.isSet(QStringLiteral("horizon"))) {
        return fail(QStringLiteral("%1 goes with --qth: the horizon is the station's").arg(label(QStringLiteral("horizon"))));
    }

    if (parser.isSet(QStringLiteral("track"))) {
        auto track = readTrack(parser, label, &error);
        if (!track)
            return fail(error);
        if (!config.station)
            return fail(QStringLiteral("--track needs --qth: where the antenna stands"));
        config.track = *track;
    } else {
        for (const char *option : {"tle", "min-el", "guard", "max-element-age", "clock-start", "clock-rate"}) {
            // With --mqtt, --tle names the satellites a remote `track` may ask for.
            if (parser.isSet(QString::fromLatin1(option)) && !(option == std::string_view("tle") && parser.isSet(QStringLiteral("mqtt"))))
                return fail(QStringLiteral("%1 goes with --track%2")
                                .arg(label(QString::fromLatin1(option)),
                                     option == std::string_view("tle") ? QStringLiteral(" or --mqtt") : QString()));
        }
    }

    if (parser.isSet(QStringLiteral("radio"))) {
        if (!config.track || config.track->target().kind != slew::tracking::TrackTarget::Kind::Satellite)
            return fail(QStringLiteral("%1 goes with --track of a satellite: Doppler is a satellite's")
                            .arg(label(QStringLiteral("radio"))));
        if (config.track->targets.size() > 1)
            return fail(QStringLiteral("%1 goes with one --track: the radio's frequencies are one satellite's (a "
                                       "schedule of several tunes no radio yet)")
                            .arg(label(QStringLiteral("radio"))));
        auto radio = readRadio(parser, label, &error);
        if (!radio)
            return fail(error);
        config.radio = *radio;
    } else {
        for (const char *option : kRadioOptions) {
            if (parser.isSet(QString::fromLatin1(option)))
                return fail(QStringLiteral("%1 goes with --radio").arg(label(QString::fromLatin1(option))));
        }
    }

    const auto records = slew::cli::readPassRecordOptions(parser, label, &error);
    if (!records)
        return fail(error);
    config.passRecords = records->path;
    config.passKeepDays = records->keepDays;
    if (parser.isSet(QStringLiteral("mqtt"))) {
        auto remote = readRemote(parser, label, &error);
        if (!remote)
            return fail(error);
        config.remote = *remote;
    } else {
        for (const char *option : {"station-name", "mqtt-password-file"}) {
            if (parser.isSet(QString::fromLatin1(option)))
                return fail(QStringLiteral("%1 goes with --mqtt").arg(label(QString::fromLatin1(option))));
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
