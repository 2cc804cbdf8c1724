// SPDX-License-Identifier: GPL-3.0-or-later
// slew-sim: the simulated rotator as a server, on TCP and/or a
// pseudo-terminal. Argument parsing and wiring only; everything else is in
// core/sim, and the options are described in cli/.
#include "cli/optionnames.h"
#include "cli/slewcommandline.h"
#include "transport/hostport.h"
#include "sim/ptyendpoint.h"
#include "sim/receivedlog.h"
#include "sim/simulator.h"
#include "sim/simulatoroptions.h"
#include "sim/simulatortcpserver.h"
#include "cli/terminationsignalwatcher.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QHostAddress>

#include <cstdio>
#include <cstdlib>
#include <memory>

using namespace slew::sim;
namespace opt = slew::cli::opt;

namespace {

void fail(const QString &message)
{
    std::fprintf(stderr, "slew-sim: %s\n", qPrintable(message));
    std::exit(2);
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("slew-sim"));
    QCoreApplication::setApplicationVersion(QStringLiteral(SLEW_VERSION));

    QCommandLineParser parser;
    slew::cli::describeTo(parser, slew::cli::slewSimMode());
    parser.process(app);

    // The simulator's own options, the same as a sim: URI's (the clock is
    // not among slew-sim's: a server always runs on the wall clock).
    SimulatorOptions options;
    for (const SimulatorOptionInfo &info : simulatorOptionList()) {
        const QString name = QString::fromLatin1(info.name);
        const QString flag = QString(name).replace(u'_', u'-');
        if (!slew::cli::slewSimMode().find(flag) || !parser.isSet(flag))
            continue;
        const QString value = QString::fromLatin1(info.valueName).isEmpty() ? QStringLiteral("1") : parser.value(flag);
        if (const QString error = applySimulatorOption(options, name, value); !error.isEmpty())
            fail(error);
    }
    if (const QString error = checkSimulatorOptions(options); !error.isEmpty())
        fail(error);

    ReceivedLog log;
    if (parser.isSet(opt::logReceived) && !log.open(parser.value(opt::logReceived)))
        fail(log.error());

    Simulator simulator(options);
    if (!simulator.stateFileError().isEmpty())
        fail(QStringLiteral("--state-file %1").arg(simulator.stateFileError()));
    // Said each time a write fails, so an operator sees why a calibration
    // did not survive a restart.
    QObject::connect(&simulator, &Simulator::stateFileFailed, [](const QString &error) {
        std::fprintf(stderr, "slew-sim: --state-file %s (the new settings are kept until exit only)\n", qPrintable(error));
    });
    ConnectionSettings settings;
    settings.dialect = options.dialect;
    settings.unsolicited = options.unsolicited;
    settings.echo = options.echo;
    settings.checksum = options.checksum;
    settings.baud = options.baud;
    settings.log = log.isOpen() ? &log : nullptr;

    QString ready = QStringLiteral("slew-sim ready");
    std::unique_ptr<SimulatorTcpServer> tcp;
    if (parser.isSet(opt::listen) || !parser.isSet(opt::pty)) {
        QHostAddress address(QHostAddress::LocalHost);
        quint16 port = 4533;
        if (parser.isSet(opt::listen) && !slew::transport::parseHostPort(parser.value(opt::listen), &address, &port))
            fail(QStringLiteral("--listen %1: expected ADDRESS:PORT").arg(parser.value(opt::listen)));
        ConnectionSettings tcpSettings = settings;
        if (parser.isSet(opt::listenDialect)) {
            const auto d = slew::protocol::dialectFromName(parser.value(opt::listenDialect));
            if (!d || *d == slew::protocol::Dialect::Rotctld) // a controller's dialect, not a network peer's
                fail(QStringLiteral("--listen-dialect %1: unknown dialect").arg(parser.value(opt::listenDialect)));
            tcpSettings.dialect = *d;
        }
        tcp = std::make_unique<SimulatorTcpServer>(simulator, tcpSettings);
        if (parser.isSet(opt::maxClients)) {
            bool ok = false;
            const int n = parser.value(opt::maxClients).toInt(&ok);
            if (!ok || n < 1 || n > 100000)
                fail(QStringLiteral("--max-clients %1: expected a number from 1 to 100000").arg(parser.value(opt::maxClients)));
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
    if (parser.isSet(opt::pty)) {
        terminal = std::make_unique<PtyEndpoint>(simulator, settings);
        if (!terminal->open(parser.value(opt::pty)))
            fail(terminal->errorString());
        ready += QStringLiteral(" pty %1 (%2)").arg(terminal->linkPath(), terminal->terminalPath());
    }
    ready += QStringLiteral(" dialect %1").arg(slew::protocol::dialectName(options.dialect));

    slew::cli::TerminationSignalWatcher terminationSignals;
    QObject::connect(&terminationSignals, &slew::cli::TerminationSignalWatcher::terminationRequested, &app, &QCoreApplication::quit);

    std::printf("%s\n", qPrintable(ready));
    std::fflush(stdout);
    const int status = app.exec();

    const FirmwareCounters &c = simulator.counters();
    std::fprintf(stderr,
                 "slew-sim: %llu lines, %llu commands, %llu rejected (%llu unknown, %llu malformed, %llu out of "
                 "limits, %llu overlong, %llu bad checksum), %llu bytes lost in the line's turn-around\n",
                 (unsigned long long)c.lines, (unsigned long long)c.commands, (unsigned long long)c.rejected(),
                 (unsigned long long)c.unknown, (unsigned long long)c.malformed, (unsigned long long)c.outOfLimits,
                 (unsigned long long)c.overlong, (unsigned long long)c.badChecksum,
                 (unsigned long long)c.lostInTurnaround);
    terminal.reset(); // removes the symlink
    return status;
}
