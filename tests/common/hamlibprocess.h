#pragma once
// Runs Hamlib's real programs (rotctl, rotctld, rigctld) from Debian's
// libhamlib-utils for the bridge and radio tests, waiting only on signals.

#include <QProcess>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>
#include <QVersionNumber>

inline QString hamlibProgram(const char *name)
{
    return QStandardPaths::findExecutable(QString::fromLatin1(name));
}

struct RotctlResult {
    bool finished = false;
    int exitCode = -1;
    QByteArray out;
    QByteArray err;
};

// One rotctl run to completion.
inline RotctlResult runRotctl(const QStringList &arguments, int timeoutMs = 20000)
{
    RotctlResult r;
    QProcess p;
    p.setProgram(hamlibProgram("rotctl"));
    p.setArguments(arguments);
    QSignalSpy finished(&p, &QProcess::finished);
    p.start();
    r.finished = finished.wait(timeoutMs) || p.state() == QProcess::NotRunning;
    if (!r.finished) {
        p.kill();
        finished.wait(5000);
    }
    r.exitCode = p.exitCode();
    r.out = p.readAllStandardOutput();
    r.err = p.readAllStandardError();
    return r;
}

// The version of Hamlib installed (Debian 12 has 4.5.4, Debian 13 4.6.2),
// from `rotctl --version`: a peer's bytes on the wire differ between them.
inline QVersionNumber hamlibVersion()
{
    const RotctlResult r = runRotctl({QStringLiteral("--version")}, 10000);
    const qsizetype at = r.out.indexOf("Hamlib ");
    return at < 0 ? QVersionNumber() : QVersionNumber::fromString(QString::fromLatin1(r.out.mid(at + 7, 16)));
}

// A free local TCP port (bound, then released for the child to take).
inline quint16 freeTcpPort()
{
    QTcpServer s;
    s.listen(QHostAddress::LocalHost, 0);
    return s.serverPort();
}

// Starts a Hamlib daemon (rigctld, rotctld) with the arguments on a free
// loopback port; returns the port once it accepts a connection, 0 if it
// never does. With tests side by side, another test's server may take the
// port between freeTcpPort() and the daemon's bind: the daemon then exits
// at once while the probe reaches the other server. So a port counts only
// while the daemon is still running a moment after the probe, and a daemon
// that died is started again on another port.
inline quint16 startHamlibDaemon(QProcess &p, const char *name, const QStringList &arguments)
{
    for (int attempt = 0; attempt < 5; ++attempt) {
        const quint16 port = freeTcpPort();
        p.setProgram(hamlibProgram(name));
        p.setArguments(arguments + QStringList{"-T", "127.0.0.1", "-t", QString::number(port)});
        p.start();
        const bool up = QTest::qWaitFor(
            [&] {
                if (p.state() == QProcess::NotRunning)
                    return true;
                QTcpSocket probe;
                QSignalSpy connected(&probe, &QTcpSocket::connected);
                probe.connectToHost(QHostAddress::LocalHost, port);
                return connected.wait(200);
            },
            10000);
        QTest::qWait(100);
        if (up && p.state() == QProcess::Running)
            return port;
        if (p.state() != QProcess::NotRunning) {
            p.kill();
            // Gone or not, the next try takes another port.
            (void)QTest::qWaitFor([&] { return p.state() == QProcess::NotRunning; }, 5000);
        }
        qWarning("%s on port %u did not come up (%s); trying another port", name, port,
                 p.readAllStandardError().left(300).constData());
    }
    return 0;
}

// Ends a daemon a test started, whoever is still connected to it: on
// SIGTERM, rigctld 4.5 exits at once, but 4.6 stops listening and then
// waits for its connected clients to leave (a command on its way gets the
// first line of its answer only). The tests end it with SIGKILL, which
// both obey at once and which closes every connection, as a daemon that
// dies or is killed does. Returns whether it is gone.
inline bool endHamlibDaemon(QProcess &p)
{
    p.kill();
    return QTest::qWaitFor([&] { return p.state() == QProcess::NotRunning; }, 5000);
}
