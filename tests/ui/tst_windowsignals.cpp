// SPDX-License-Identifier: GPL-3.0-or-later
// `slew` with its window, run as a real process against slew-sim: on
// SIGTERM or SIGINT it stops the rotator before it exits, as the station
// service does.

#include "../sim/slewsimprocess.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>

class WindowSignalsTest : public QObject {
    Q_OBJECT
private slots:
    void signalStopsTheRotatorBeforeExit_data();
    void signalStopsTheRotatorBeforeExit();
};

void WindowSignalsTest::signalStopsTheRotatorBeforeExit_data()
{
    QTest::addColumn<int>("signalNumber");
    QTest::newRow("SIGTERM") << int(SIGTERM);
    QTest::newRow("SIGINT") << int(SIGINT);
}

void WindowSignalsTest::signalStopsTheRotatorBeforeExit()
{
    QFETCH(int, signalNumber);
    QTemporaryDir dir;
    const QString received = dir.filePath("received.log");
    SlewSimProcess sim;
    QVERIFY2(sim.start({"--listen", "127.0.0.1:0", "--log-received", received}), qPrintable(sim.error()));
    auto log = [&] {
        QFile f(received);
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    };

    QProcess slew;
    slew.setProgram(qEnvironmentVariable("SLEW_BIN"));
    slew.setArguments({"--connect", QStringLiteral("tcp://127.0.0.1:%1").arg(sim.port()), "--goto", "120,30"});
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("QT_QPA_PLATFORM", "offscreen");
    env.insert("XDG_CONFIG_HOME", dir.filePath("config")); // the window remembers its connection there
    slew.setProcessEnvironment(env);
    slew.start();
    // Moving: the go-to has reached the rotator.
    QTRY_VERIFY_WITH_TIMEOUT(log().contains("AZ120.00 EL30.00"), 15000);
    const qsizetype stopsBefore = log().count("SA SE");

    QSignalSpy finished(&slew, &QProcess::finished);
    ::kill(pid_t(slew.processId()), signalNumber);
    QVERIFY(finished.wait(10000));
    QCOMPARE(slew.exitStatus(), QProcess::NormalExit);
    QCOMPARE(slew.exitCode(), 0);
    QTRY_VERIFY(log().count("SA SE") > stopsBefore);
    QVERIFY(slew.readAllStandardError().contains("stopping the rotator"));
}

QTEST_GUILESS_MAIN(WindowSignalsTest)
#include "tst_windowsignals.moc"
