// SPDX-License-Identifier: GPL-3.0-or-later
// How the session polls a SPID controller on a slow line: a Rot2Prog at
// 600 baud and a Rot1Prog at 1200 (their own rates), and an MD-01 at 9600,
// each on the simulator's SPID firmware paced to that rate, for two
// simulated minutes on the manual clock while the rotator slews. Printed:
// polls a second, their share of what the line carries, and requests that
// failed. Without pacing, the profile's 10 Hz would ask for 417 % of the
// Rot2Prog line (bench_spidparser).
//
// Beside it, the peer: Hamlib's rotctld (model 901) on slew-sim's pty at
// 600 baud, asked `p` as fast as a client can for ten seconds of wall
// time, as a tracker that polls faster than the line would.

#include "common/simulatorpump.h"
#include "linkschemes.h"
#include "protocol/spidcodec.h"
#include "session/rotatorsession.h"

#include "common/hamlibprocess.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QProcess>
#include <QTcpSocket>
#include <QTemporaryDir>

#include <cstdio>

using namespace slew;
using protocol::Dialect;

namespace {

constexpr double kSeconds = 120.0;

void run(Dialect d, int baud)
{
    session::RotatorSession s;
    model::RotatorProfile profile;
    profile.dialect = d;
    profile.limits = model::RotatorLimits{0, 360, 0, d == Dialect::Rot1Prog ? 0.0 : 90.0};
    s.setProfile(profile);
    s.connectTo(QStringLiteral("sim:?clock=manual&dialect=%1&baud=%2&start_az=10&start_el=10")
                    .arg(protocol::dialectName(d))
                    .arg(baud));
    SimulatorPump pump(0.005);
    pump.follow(&s);
    if (!runEventLoopUntil([&] { return s.capabilities().probed && s.hasPosition(); }, 30000)) {
        std::printf("%s: no position\n", qPrintable(protocol::dialectName(d)));
        return;
    }
    sim::Simulator *sim = sim::simulatorBehind(s.link());
    int polls = 0, failed = 0, positions = 0;
    QObject::connect(&s, &session::RotatorSession::bytesSent, &s, [&](const QByteArray &bytes) {
        polls += bytes == protocol::spid::encodeStatus() ? 1 : 0;
    });
    QObject::connect(&s, &session::RotatorSession::requestFailed, &s, [&] { ++failed; });
    QObject::connect(&s, &session::RotatorSession::positionChanged, &s, [&](double, double, bool stale) {
        positions += stale ? 0 : 1;
    });
    const double start = sim->clock().now();
    s.gotoPosition(300, d == Dialect::Rot1Prog ? 0 : 80); // a long slew meanwhile
    runEventLoopUntil([&] { return sim->clock().now() - start >= kSeconds; }, 600000);
    const double elapsed = sim->clock().now() - start;
    const int bytes = protocol::spid::kCommandSize + protocol::spid::replySize(d);
    const double lineCarries = baud / 10.0 / bytes;
    std::printf("%-9s at %5d baud: poll every %4d ms (reply timeout %4d ms): %.2f polls/s, %.0f %% of the %.2f "
                "the line carries; %.2f positions/s, %d failed requests\n",
                qPrintable(protocol::dialectName(d)), baud, s.pollIntervalMs(), s.replyTimeoutMs(), polls / elapsed,
                100.0 * polls / elapsed / lineCarries, lineCarries, positions / elapsed, failed);
    s.stop(QStringLiteral("the test"));
}

// Hamlib's rotctld in front of a Rot2Prog at 600 baud, asked `p` back to
// back: how many answers a second, and how long each takes.
void runHamlibPeer()
{
    const QString rotctld = hamlibProgram("rotctld");
    if (rotctld.isEmpty()) {
        std::printf("Hamlib rotctld: not installed (libhamlib-utils)\n");
        return;
    }
    QTemporaryDir dir;
    const QString pty = dir.filePath(QStringLiteral("rot2prog"));
    QProcess sim, hamlib;
    sim.start(QStringLiteral(SLEW_SIM_BIN), {"--pty", pty, "--dialect", "rot2prog", "--baud", "600"});
    if (!runEventLoopUntil([&] { return QFile::exists(pty); }, 10000)) {
        std::printf("Hamlib rotctld: slew-sim did not start\n");
        return;
    }
    const quint16 port = freeTcpPort();
    hamlib.start(rotctld, {"-m", "901", "-r", pty, "-s", "600", "-T", "127.0.0.1", "-t", QString::number(port)});
    QTcpSocket client;
    const bool connected = runEventLoopUntil([&] {
        if (client.state() == QAbstractSocket::UnconnectedState)
            client.connectToHost(QHostAddress::LocalHost, port);
        return client.state() == QAbstractSocket::ConnectedState;
    }, 10000);
    if (!connected) {
        std::printf("Hamlib rotctld: no connection\n");
        return;
    }
    int answers = 0, lines = 0;
    double sumMs = 0, worstMs = 0;
    QElapsedTimer asked, wall;
    QObject::connect(&client, &QTcpSocket::readyRead, &client, [&] {
        while (client.canReadLine()) {
            client.readLine();
            if (++lines % 2 != 0)
                continue; // a `p` answers two lines
            const double ms = asked.nsecsElapsed() / 1e6;
            ++answers;
            sumMs += ms;
            worstMs = std::max(worstMs, ms);
            asked.start();
            client.write("p\n");
        }
    });
    wall.start();
    asked.start();
    client.write("p\n");
    runEventLoopUntil([&] { return wall.elapsed() >= 10000; }, 20000);
    const double seconds = wall.elapsed() / 1000.0;
    const double lineCarries = 600 / 10.0 / (protocol::spid::kCommandSize + protocol::spid::kReplySize);
    std::printf("Hamlib rotctld (901) at 600 baud, `p` back to back: %.2f answers/s, %.0f %% of the line; "
                "%.0f ms each (worst %.0f ms)\n",
                answers / seconds, 100.0 * answers / seconds / lineCarries, sumMs / std::max(1, answers), worstMs);
    client.disconnectFromHost();
    hamlib.terminate();
    sim.terminate();
    runEventLoopUntil([&] { return hamlib.state() == QProcess::NotRunning && sim.state() == QProcess::NotRunning; }, 5000);
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    registerLinkSchemes();
    run(Dialect::Rot2Prog, 600);
    run(Dialect::Rot1Prog, 1200);
    run(Dialect::Md01, 9600);
    runHamlibPeer();
    return 0;
}
