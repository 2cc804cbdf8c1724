// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Starts slew-sim (SLEW_SIM_BIN) as a child process for a test, reads its
// ready line, and stops it with SIGTERM at the end. Waits only on signals.

#include <QProcess>
#include <QSignalSpy>
#include <QString>
#include <QStringList>
#include <QTcpSocket>
#include <QTest>

#include <functional>
#include <memory>

class SlewSimProcess {
public:
    ~SlewSimProcess() { stop(); }

    // Starts it and waits for the ready line; false (with error()) if it fails.
    // childSetup runs in the child before slew-sim starts (e.g. setrlimit).
    bool start(const QStringList &arguments, const std::function<void()> &childSetup = {})
    {
        const QString program = qEnvironmentVariable("SLEW_SIM_BIN");
        if (program.isEmpty()) {
            m_error = "SLEW_SIM_BIN is not set";
            return false;
        }
        m_process = std::make_unique<QProcess>();
        m_process->setProgram(program);
        m_process->setArguments(arguments);
        m_process->setProcessChannelMode(QProcess::SeparateChannels);
        if (childSetup)
            m_process->setChildProcessModifier(childSetup);
        m_process->start();
        // Ready line or exit, whichever comes first: a refused flag ends it
        // at once, and waiting on the ready line alone would sit out the limit.
        const bool settled = QTest::qWaitFor(
            [&] { return m_process->canReadLine() || m_process->state() == QProcess::NotRunning; }, 10000);
        if (!settled || !m_process->canReadLine()) {
            m_error = "slew-sim did not start: " + QString::fromLocal8Bit(m_process->readAllStandardError());
            return false;
        }
        m_readyLine = QString::fromLocal8Bit(m_process->readLine()).trimmed();
        const QStringList words = m_readyLine.split(' ');
        const qsizetype tcp = words.indexOf("tcp");
        if (tcp >= 0 && tcp + 1 < words.size())
            m_port = quint16(words[tcp + 1].section(':', -1).toUInt());
        return true;
    }

    // SIGTERM, then wait for a clean exit; returns the exit code (-1 on a crash or hang).
    int stop()
    {
        if (!m_process || m_process->state() == QProcess::NotRunning)
            return m_process && m_process->exitStatus() == QProcess::NormalExit ? m_process->exitCode() : -1;
        QSignalSpy finished(m_process.get(), &QProcess::finished);
        m_process->terminate();
        if (!finished.wait(5000)) {
            m_process->kill();
            finished.wait(5000);
            return -1;
        }
        m_stderr += m_process->readAllStandardError();
        return m_process->exitStatus() == QProcess::NormalExit ? m_process->exitCode() : -1;
    }

    QProcess *process() const { return m_process.get(); }
    QString readyLine() const { return m_readyLine; }
    quint16 port() const { return m_port; }
    QString error() const { return m_error; }
    QByteArray standardError() const { return m_stderr; }

private:
    std::unique_ptr<QProcess> m_process;
    QString m_readyLine;
    QString m_error;
    QByteArray m_stderr;
    quint16 m_port = 0;
};

// A line-oriented TCP client for the simulator.
class SimClient {
public:
    bool connectTo(quint16 port)
    {
        QSignalSpy connected(&m_socket, &QTcpSocket::connected);
        m_socket.connectToHost(QHostAddress::LocalHost, port);
        return connected.wait(5000);
    }

    // Sends bytes and returns the next `lines` reply lines (joined, with their '\n').
    QByteArray ask(const QByteArray &bytes, int lines = 1)
    {
        m_socket.write(bytes);
        return readLines(lines);
    }

    QByteArray readLines(int lines)
    {
        QByteArray got;
        QSignalSpy ready(&m_socket, &QTcpSocket::readyRead);
        for (int i = 0; i < lines; ++i) {
            while (!m_socket.canReadLine()) {
                if (!ready.wait(5000))
                    return got;
            }
            got += m_socket.readLine();
        }
        return got;
    }

    QTcpSocket &socket() { return m_socket; }

private:
    QTcpSocket m_socket;
};
