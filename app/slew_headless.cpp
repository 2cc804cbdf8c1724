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
#include "protocol/dialect.h"
#include "sim/terminationsignalwatcher.h"

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

} // namespace

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
    const QString connect = QStringLiteral("connect"), dialect = QStringLiteral("dialect"),
                  profile = QStringLiteral("profile"), listen = QStringLiteral("rotctld-listen"),
                  allow = QStringLiteral("rotctld-allow");

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

    slew::bridge::HeadlessStation station;
    if (!station.start(config, &error))
        return fail(error);

    slew::sim::TerminationSignalWatcher terminationSignals;
    QObject::connect(&terminationSignals, &slew::sim::TerminationSignalWatcher::terminationRequested, &station,
                     [&station](int number) { station.shutdown(QStringLiteral("signal %1").arg(number)); });
    QObject::connect(&station, &slew::bridge::HeadlessStation::finished, &app, &QCoreApplication::quit);
    return app.exec();
}
