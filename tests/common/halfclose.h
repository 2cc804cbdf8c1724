// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Test clients for the servers' edge cases: one that shuts down its sending
// side right after its request (as `nc -N` and `socat -t` do), and the CPU
// time a child process has used, from /proc.

#include <QFile>
#include <QHostAddress>
#include <QSignalSpy>
#include <QElapsedTimer>
#include <QTcpSocket>
#include <QTimer>

#include <list>

#include <sys/socket.h>
#include <unistd.h>

// Connects, writes `request`, shuts down the sending side at once, and
// returns everything the server sent before it closed (empty on a timeout).
inline QByteArray askThenHalfClose(quint16 port, const QByteArray &request, int timeoutMs = 5000)
{
    QTcpSocket s;
    QSignalSpy connected(&s, &QTcpSocket::connected);
    s.connectToHost(QHostAddress::LocalHost, port);
    if (!connected.wait(timeoutMs))
        return {};
    s.write(request);
    s.flush();
    ::shutdown(int(s.socketDescriptor()), SHUT_WR);
    QSignalSpy gone(&s, &QTcpSocket::disconnected);
    if (s.state() == QAbstractSocket::ConnectedState && !gone.wait(timeoutMs))
        return {};
    return s.readAll();
}

// utime + stime of a process, in clock ticks (-1 if it cannot be read).
inline qint64 processCpuTicks(qint64 pid)
{
    QFile f(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!f.open(QIODevice::ReadOnly))
        return -1;
    const QByteArray stat = f.readAll();
    // Fields after the command name, which is in parentheses and may hold spaces.
    const QList<QByteArray> fields = stat.mid(stat.lastIndexOf(')') + 2).split(' ');
    if (fields.size() < 13)
        return -1;
    return fields[11].toLongLong() + fields[12].toLongLong();
}

inline double clockTicksPerSecond()
{
    return double(::sysconf(_SC_CLK_TCK));
}

// The share of one core a process uses over about `ms` of wall time, the
// window waited out on the event loop. A rate needs a window: a server that
// retries accept() in a loop burns the whole of it. -1 if it cannot be read.
inline double cpuShareOver(qint64 pid, int ms)
{
    const qint64 before = processCpuTicks(pid);
    QElapsedTimer window;
    window.start();
    QTimer end;
    end.setSingleShot(true);
    QSignalSpy ended(&end, &QTimer::timeout);
    end.start(ms);
    if (before < 0 || !ended.wait(ms + 10000))
        return -1;
    const double seconds = (processCpuTicks(pid) - before) / clockTicksPerSecond();
    return seconds / (window.elapsed() / 1000.0);
}

// For QTest::qWaitFor: takes the one answer each client is owed as it
// comes, counts it, keeps any that is not `expected`, and drops answered
// clients; true once every client has answered.
inline bool takeOneAnswerEach(std::list<QTcpSocket> &clients, const QByteArray &expected, int *answered,
                              QByteArray *wrong)
{
    for (auto it = clients.begin(); it != clients.end();) {
        if (!it->canReadLine()) {
            ++it;
            continue;
        }
        if (const QByteArray a = it->readAll(); a != expected)
            *wrong += a;
        ++*answered;
        it = clients.erase(it);
    }
    return clients.empty();
}
