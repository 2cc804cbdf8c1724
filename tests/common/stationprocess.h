// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `slew --headless ARGS` as a station service runs (no display), and its
// log as it comes. SLEW_BIN names the program.

#include <QProcess>
#include <QSignalSpy>
#include <QTest>

#include <csignal>

struct StationProcess {
    QProcess process;
    QByteArray out;
    QByteArray err;

    // `password`, when given, reaches it as SLEW_MQTT_PASSWORD.
    explicit StationProcess(const QStringList &arguments, const QString &password = {})
    {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove(QStringLiteral("DISPLAY"));
        env.remove(QStringLiteral("QT_QPA_PLATFORM"));
        if (!password.isEmpty())
            env.insert(QStringLiteral("SLEW_MQTT_PASSWORD"), password);
        process.setProcessEnvironment(env);
        process.start(qEnvironmentVariable("SLEW_BIN"), QStringList{QStringLiteral("--headless")} + arguments);
    }
    ~StationProcess()
    {
        if (process.state() != QProcess::NotRunning) {
            QSignalSpy finished(&process, &QProcess::finished);
            process.kill();
            finished.wait(5000);
        }
    }
    // Whether the log says `text` within `ms` (the process ending stops the wait).
    bool logged(const QByteArray &text, int ms = 20000)
    {
        return QTest::qWaitFor(
                   [&] {
                       out += process.readAllStandardOutput();
                       return out.contains(text) || process.state() == QProcess::NotRunning;
                   },
                   ms)
               && out.contains(text);
    }
    // Everything so far, errors too; what it reads stays in `out` and `err`.
    QByteArray said()
    {
        out += process.readAllStandardOutput();
        err += process.readAllStandardError();
        return out + err;
    }
    // Sends the signal and waits for the end: the exit code, 128 + signal
    // when it was killed, -1 when it did not end.
    int stop(int signal)
    {
        QSignalSpy finished(&process, &QProcess::finished);
        ::kill(pid_t(process.processId()), signal);
        if (!finished.wait(15000))
            return -1;
        return process.exitStatus() == QProcess::NormalExit ? process.exitCode() : 128 + signal;
    }
};
