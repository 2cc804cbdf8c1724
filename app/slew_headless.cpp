// SPDX-License-Identifier: GPL-3.0-or-later
// `slew --headless --connect URI --rotctld-listen ADDR:PORT`: argument parsing
// and wiring for the station service; the work is in core/bridge.

#include "slew_identity.h"
#include "transport/hostport.h"
#include "slew_headless.h"

#include "bridge/headlessstation.h"
#include "bridge/rotctldserver.h"
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

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Slew as a station service: no window, log on stdout."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption headless(QStringLiteral("headless"), QStringLiteral("Run without a window."));
    const QCommandLineOption connect(QStringLiteral("connect"), QStringLiteral("The rotator's link URI (default sim:)."),
                                     QStringLiteral("URI"));
    const QCommandLineOption dialect(QStringLiteral("dialect"),
                                     QStringLiteral("One of: %1.").arg(slew::protocol::dialectNameList()),
                                     QStringLiteral("name"));
    const QCommandLineOption profile(QStringLiteral("profile"), QStringLiteral("A rotator profile (JSON) to load."),
                                     QStringLiteral("file"));
    const QCommandLineOption listen(QStringLiteral("rotctld-listen"),
                                    QStringLiteral("Serve rotctld on ADDRESS:PORT (127.0.0.1 unless named)."),
                                    QStringLiteral("address:port"));
    const QCommandLineOption allow(QStringLiteral("rotctld-allow"),
                                   QStringLiteral("Comma-separated client addresses allowed (default: any)."),
                                   QStringLiteral("addresses"));
    const QCommandLineOption maxClients(
        QStringLiteral("rotctld-max-clients"),
        QStringLiteral("rotctld clients at once (default %1); one more reads RPRT -9 and is closed.")
            .arg(slew::bridge::RotctldServer::kDefaultMaxClients),
        QStringLiteral("n"));
    parser.addOptions({headless, connect, dialect, profile, listen, allow, maxClients});
    parser.process(app);

    slew::bridge::HeadlessConfig config;
    if (parser.isSet(profile)) {
        QString error;
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

    if (parser.isSet(maxClients)) {
        const auto n = parseMaxClients(parser.value(maxClients));
        if (!n)
            return fail(QStringLiteral("--rotctld-max-clients %1: expected a number from 1 to 100000")
                            .arg(parser.value(maxClients)));
        config.rotctldMaxClients = *n;
    }

    slew::bridge::HeadlessStation station;
    QString error;
    if (!station.start(config, &error))
        return fail(error);

    slew::sim::TerminationSignalWatcher terminationSignals;
    QObject::connect(&terminationSignals, &slew::sim::TerminationSignalWatcher::terminationRequested, &station,
                     [&station](int number) { station.shutdown(QStringLiteral("signal %1").arg(number)); });
    QObject::connect(&station, &slew::bridge::HeadlessStation::finished, &app, &QCoreApplication::quit);
    return app.exec();
}
