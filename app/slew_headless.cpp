// SPDX-License-Identifier: GPL-3.0-or-later
// `slew --headless --connect URI --rotctld-listen ADDR:PORT`: argument parsing
// and wiring for the station service; the work is in core/bridge. The
// options are described in cli/.

#include "slew_identity.h"
#include "cli/configfile.h"
#include "cli/slewcommandline.h"
#include "transport/hostport.h"
#include "slew_headless.h"

#include "bridge/headlessstation.h"
#include "bridge/rotctldserver.h"
#include "protocol/dialect.h"
#include "transport/linkfactory.h"
#include "cli/terminationsignalwatcher.h"
#include "sky/tle.h"
#include "sky/utctime.h"

#include <QFile>

#include <QCommandLineParser>
#include <QCoreApplication>

#include <cstdio>
#include <cstring>

namespace {

int fail(const QString &message)
{
    std::fprintf(stderr, "slew: %s\n", qPrintable(message));
    return 2;
}

// --track and what goes with it: the target (a satellite from --tle, the
// sun, the moon, azel:AZ,EL or radec:RA,DEC), --min-el, --clock-start,
// --clock-rate.
std::optional<slew::bridge::HeadlessConfig::Track> readTrack(const QCommandLineParser &parser, QString *error)
{
    using slew::tracking::TrackTarget;
    slew::bridge::HeadlessConfig::Track track;
    const QString what = parser.value(QStringLiteral("track")).trimmed();
    QString badFixed;
    if (const auto fixed = TrackTarget::parseFixedOrCelestial(what, &badFixed)) {
        track.target = *fixed;
    } else if (!badFixed.isEmpty()) {
        *error = QStringLiteral("--track %1").arg(badFixed);
        return std::nullopt;
    } else if (what.compare(QLatin1String("sun"), Qt::CaseInsensitive) == 0) {
        track.target.kind = TrackTarget::Kind::Sun;
    } else if (what.compare(QLatin1String("moon"), Qt::CaseInsensitive) == 0) {
        track.target.kind = TrackTarget::Kind::Moon;
    } else {
        if (!parser.isSet(QStringLiteral("tle"))) {
            *error = QStringLiteral("--track %1 needs --tle FILE with its element set").arg(what);
            return std::nullopt;
        }
        QFile file(parser.value(QStringLiteral("tle")));
        if (!file.open(QIODevice::ReadOnly)) {
            *error = QStringLiteral("--tle %1: %2").arg(file.fileName(), file.errorString());
            return std::nullopt;
        }
        const QList<slew::sky::Tle> sets = slew::sky::readTleText(QString::fromLatin1(file.readAll())).sets;
        const QList<const slew::sky::Tle *> found = slew::sky::findTles(sets, what);
        if (found.isEmpty()) {
            *error = QStringLiteral("--track %1: no such satellite in %2").arg(what, file.fileName());
            return std::nullopt;
        }
        track.target.elements = *found.first();
    }
    if (parser.isSet(QStringLiteral("min-el"))) {
        bool ok = false;
        track.minElevationDeg = parser.value(QStringLiteral("min-el")).toDouble(&ok);
        if (!ok || track.minElevationDeg < -5 || track.minElevationDeg > 90) {
            *error = QStringLiteral("--min-el %1: expected degrees from -5 to 90").arg(parser.value(QStringLiteral("min-el")));
            return std::nullopt;
        }
    }
    if (parser.isSet(QStringLiteral("clock-start"))) {
        track.clockStartJulian = slew::sky::julianFromIso(parser.value(QStringLiteral("clock-start")));
        if (!track.clockStartJulian) {
            *error = QStringLiteral("--clock-start %1: expected an ISO 8601 time, as 2024-06-20T12:00:00Z")
                         .arg(parser.value(QStringLiteral("clock-start")));
            return std::nullopt;
        }
    }
    if (parser.isSet(QStringLiteral("clock-rate"))) {
        bool ok = false;
        track.clockRate = parser.value(QStringLiteral("clock-rate")).toDouble(&ok);
        if (!ok || track.clockRate < 1 || track.clockRate > 20 || !track.clockStartJulian) {
            *error = QStringLiteral("--clock-rate %1: expected 1 to 20, with --clock-start")
                         .arg(parser.value(QStringLiteral("clock-rate")));
            return std::nullopt;
        }
    }
    return track;
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
    const auto arguments = slew::cli::withConfigFile(app.arguments(), slew::cli::slewHeadlessMode(), &error);
    if (!arguments)
        return fail(error);
    QCommandLineParser parser;
    slew::cli::describeTo(parser, slew::cli::slewHeadlessMode());
    parser.process(*arguments);
    checkSettingsFile(); // saved calibrations are read from them
    const QString connect = QStringLiteral("connect"), dialect = QStringLiteral("dialect"),
                  profile = QStringLiteral("profile"), listen = QStringLiteral("rotctld-listen"),
                  allow = QStringLiteral("rotctld-allow"), maxClients = QStringLiteral("rotctld-max-clients");

    slew::bridge::HeadlessConfig config;
    if (parser.isSet(profile)) {
        auto loaded = slew::model::RotatorProfile::load(parser.value(profile), &error);
        if (!loaded)
            return fail(error);
        config.profile = *loaded;
    }
    if (parser.isSet(connect))
        config.profile.uri = parser.value(connect);
    if (parser.isSet(dialect)) {
        const auto d = slew::protocol::dialectFromName(parser.value(dialect));
        if (!d)
            return fail(QStringLiteral("unknown dialect '%1'").arg(parser.value(dialect)));
        config.profile.dialect = *d;
    } else if (!parser.isSet(profile)) {
        // Neither names one: the link may (a simulator's `dialect=`), as the
        // window's connection bar takes it.
        if (const auto d = slew::protocol::dialectFromName(slew::transport::linkHintsFor(config.profile.uri).dialect))
            config.profile.dialect = *d;
    }
    if (parser.isSet(listen)) {
        if (!slew::transport::parseHostPort(parser.value(listen), &config.rotctldAddress, &config.rotctldPort))
            return fail(QStringLiteral("--rotctld-listen %1: expected ADDRESS:PORT").arg(parser.value(listen)));
        config.rotctldEnabled = true;
    }
    if (parser.isSet(allow)) {
        for (const QString &a : parser.value(allow).split(u',', Qt::SkipEmptyParts)) {
            const QHostAddress address(a.trimmed());
            if (address.isNull())
                return fail(QStringLiteral("--rotctld-allow: '%1' is not an address").arg(a));
            config.allowedClients.append(address);
        }
    }

    if (parser.isSet(maxClients)) {
        const auto n = parseMaxClients(parser.value(maxClients));
        if (!n)
            return fail(QStringLiteral("--rotctld-max-clients %1: expected a number from 1 to 100000")
                            .arg(parser.value(maxClients)));
        config.rotctldMaxClients = *n;
    }

    if (parser.isSet(QStringLiteral("rotors"))) {
        const QString list = parser.value(QStringLiteral("rotors"));
        const auto rotors = slew::bridge::parseRotorList(list, &error);
        if (!rotors)
            return fail(QStringLiteral("--rotors %1: %2").arg(list, error));
        config.rotors = *rotors;
    }

    if (parser.isSet(QStringLiteral("limits"))) {
        const QString text = parser.value(QStringLiteral("limits"));
        const auto limits = slew::bridge::parseLimits(text, &error);
        if (!limits)
            return fail(QStringLiteral("--limits %1: %2").arg(text, error));
        config.profile.limits = *limits;
    }

    if (parser.isSet(QStringLiteral("qth"))) {
        slew::sky::Station where;
        if (!slew::sky::parseStation(parser.value(QStringLiteral("qth")), &where, &error))
            return fail(QStringLiteral("--qth %1: %2").arg(parser.value(QStringLiteral("qth")), error));
        config.station = where;
    }

    if (parser.isSet(QStringLiteral("track"))) {
        auto track = readTrack(parser, &error);
        if (!track)
            return fail(error);
        if (!config.station)
            return fail(QStringLiteral("--track needs --qth: where the antenna stands"));
        config.track = *track;
    } else {
        for (const char *option : {"tle", "min-el", "clock-start", "clock-rate"}) {
            if (parser.isSet(QString::fromLatin1(option)))
                return fail(QStringLiteral("--%1 goes with --track").arg(QString::fromLatin1(option)));
        }
    }

    slew::bridge::HeadlessStation station;
    if (!station.start(config, &error))
        return fail(error);

    slew::cli::TerminationSignalWatcher terminationSignals;
    QObject::connect(&terminationSignals, &slew::cli::TerminationSignalWatcher::terminationRequested, &station,
                     [&station](int number) { station.shutdown(QStringLiteral("signal %1").arg(number)); });
    QObject::connect(&station, &slew::bridge::HeadlessStation::finished, &app, &QCoreApplication::quit);
    return app.exec();
}
