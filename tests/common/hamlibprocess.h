#pragma once
// Runs Hamlib's real programs (rotctl, rotctld) from Debian's libhamlib-utils
// for the bridge tests, waiting only on signals.

#include <QProcess>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTcpServer>
#include <QTest>

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

// A free local TCP port (bound, then released for the child to take).
inline quint16 freeTcpPort()
{
    QTcpServer s;
    s.listen(QHostAddress::LocalHost, 0);
    return s.serverPort();
}
