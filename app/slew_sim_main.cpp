// SPDX-License-Identifier: GPL-3.0-or-later
// slew-sim: the simulated rotator as a server, on TCP and/or a
// pseudo-terminal. Argument parsing and wiring only; everything else is in
// core/sim.
#include "transport/hostport.h"
#include "sim/ptyendpoint.h"
#include "sim/receivedlog.h"
#include "sim/simulator.h"
#include "sim/simulatoroptions.h"
#include "sim/simulatortcpserver.h"
#include "sim/terminationsignalwatcher.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QHostAddress>

#include <cstdio>
#include <cstdlib>
#include <memory>

using namespace slew::sim;

namespace {

void fail(const QString &message)
{
    std::fprintf(stderr, "slew-sim: %s\n", qPrintable(message));
    std::exit(2);
}

// "127.0.0.1:4533", "[::1]:0", ":4533" (loopback)

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("slew-sim"));

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Simulated Easycomm az/el rotator, served on TCP and/or a pseudo-terminal."));
    parser.addHelpOption();
    const QCommandLineOption listen(QStringLiteral("listen"), QStringLiteral("serve TCP on ADDRESS:PORT (port 0: any free port)"),
                                    QStringLiteral("address:port"));
    const QCommandLineOption pty(QStringLiteral("pty"), QStringLiteral("serve a pseudo-terminal, symlinked at PATH"),
                                 QStringLiteral("path"));
    const QCommandLineOption listenDialect(QStringLiteral("listen-dialect"),
                                           QStringLiteral("dialect of the TCP endpoint if not --dialect's"),
                                           QStringLiteral("name"));
    const QCommandLineOption logReceived(QStringLiteral("log-received"),
                                         QStringLiteral("write every line received to FILE"), QStringLiteral("file"));
    const QCommandLineOption maxClients(
        QStringLiteral("max-clients"),
        QStringLiteral("TCP clients at once (default %1); one more is refused").arg(SimulatorTcpServer::kDefaultMaxClients),
        QStringLiteral("n"));
    parser.addOptions({listen, pty, listenDialect, logReceived, maxClients});

    std::vector<std::pair<QCommandLineOption, const char *>> simOptions;
    for (const SimulatorOptionInfo &info : simulatorOptionList()) {
        const QString name = QString::fromLatin1(info.name);
        QStringList names{QString(name).replace(u'_', u'-')};
        if (name.contains(u'_'))
            names << name;
        QCommandLineOption option(names, QString::fromLatin1(info.description), QString::fromLatin1(info.valueName));
        if (names.first() == u"clock")
            continue; // a server always runs on the wall clock
        parser.addOption(option);
        simOptions.emplace_back(option, info.name);
    }
    parser.process(app);

    SimulatorOptions options;
    for (const auto &[option, name] : simOptions) {
        if (!parser.isSet(option))
            continue;
        const QString value = option.valueName().isEmpty() ? QStringLiteral("1") : parser.value(option);
        if (const QString error = applySimulatorOption(options, QString::fromLatin1(name), value); !error.isEmpty())
            fail(error);
    }

    ReceivedLog log;
    if (parser.isSet(logReceived) && !log.open(parser.value(logReceived)))
        fail(log.error());

    Simulator simulator(options);
    ConnectionSettings settings;
    settings.dialect = options.dialect;
    settings.unsolicited = options.unsolicited;
    settings.baud = options.baud;
    settings.log = log.isOpen() ? &log : nullptr;

    QString ready = QStringLiteral("slew-sim ready");
    std::unique_ptr<SimulatorTcpServer> tcp;
    if (parser.isSet(listen) || !parser.isSet(pty)) {
        QHostAddress address(QHostAddress::LocalHost);
        quint16 port = 4533;
        if (parser.isSet(listen) && !slew::transport::parseHostPort(parser.value(listen), &address, &port))
            fail(QStringLiteral("--listen %1: expected ADDRESS:PORT").arg(parser.value(listen)));
        ConnectionSettings tcpSettings = settings;
        if (parser.isSet(listenDialect)) {
            const auto d = slew::protocol::dialectFromName(parser.value(listenDialect));
            if (!d)
                fail(QStringLiteral("--listen-dialect %1: unknown dialect").arg(parser.value(listenDialect)));
            tcpSettings.dialect = *d;
        }
        tcp = std::make_unique<SimulatorTcpServer>(simulator, tcpSettings);
        if (parser.isSet(maxClients)) {
            bool ok = false;
            const int n = parser.value(maxClients).toInt(&ok);
            if (!ok || n < 1 || n > 100000)
                fail(QStringLiteral("--max-clients %1: expected a number from 1 to 100000").arg(parser.value(maxClients)));
            tcp->setMaxClients(n);
        }
        QObject::connect(tcp.get(), &SimulatorTcpServer::notice, [](const QString &text) {
            std::fprintf(stderr, "slew-sim: %s\n", qPrintable(text));
        });
        if (!tcp->listen(address, port))
            fail(QStringLiteral("cannot listen on %1:%2: %3").arg(address.toString()).arg(port).arg(tcp->errorString()));
        ready += QStringLiteral(" tcp %1:%2").arg(tcp->serverAddress().toString()).arg(tcp->serverPort());
    }
    std::unique_ptr<PtyEndpoint> terminal;
    if (parser.isSet(pty)) {
        terminal = std::make_unique<PtyEndpoint>(simulator, settings);
        if (!terminal->open(parser.value(pty)))
            fail(terminal->errorString());
        ready += QStringLiteral(" pty %1 (%2)").arg(terminal->linkPath(), terminal->terminalPath());
    }
    ready += QStringLiteral(" dialect %1").arg(slew::protocol::dialectName(options.dialect));

    TerminationSignalWatcher terminationSignals;
    QObject::connect(&terminationSignals, &TerminationSignalWatcher::terminationRequested, &app, &QCoreApplication::quit);

    std::printf("%s\n", qPrintable(ready));
    std::fflush(stdout);
    const int status = app.exec();

    const FirmwareCounters &c = simulator.counters();
    std::fprintf(stderr,
                 "slew-sim: %llu lines, %llu commands, %llu rejected (%llu unknown, %llu malformed, %llu out of "
                 "limits, %llu overlong)\n",
                 (unsigned long long)c.lines, (unsigned long long)c.commands, (unsigned long long)c.rejected(),
                 (unsigned long long)c.unknown, (unsigned long long)c.malformed, (unsigned long long)c.outOfLimits,
                 (unsigned long long)c.overlong);
    terminal.reset(); // removes the symlink
    return status;
}
