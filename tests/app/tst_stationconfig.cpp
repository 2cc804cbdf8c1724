// SPDX-License-Identifier: GPL-3.0-or-later
// The station service as systemd starts it: the real slew binary with
// --headless --config FILE, the installed example file, a broken file, and
// the manual pages next to what the binaries' --help prints.

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QSignalSpy>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>

class StationConfigTest : public QObject {
    Q_OBJECT
private slots:
    void exampleFileStartsAStation();
    void brokenFileIsRefusedWithItsLine();
    void manualPagesMatchHelp_data();
    void manualPagesMatchHelp();

private:
    static QProcessEnvironment serviceEnvironment();
};

QProcessEnvironment StationConfigTest::serviceEnvironment()
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove("QT_QPA_PLATFORM");
    env.remove("DISPLAY");
    env.remove("WAYLAND_DISPLAY"); // a service has no display
    return env;
}

void StationConfigTest::exampleFileStartsAStation()
{
    // The file the package installs as /etc/slew/example.conf, with the
    // rotctld port moved to a free one on the command line, which wins.
    const QString example = qEnvironmentVariable("SLEW_SOURCE_DIR") + "/packaging/example.conf";
    QVERIFY(QFile::exists(example));
    QProcess slew;
    slew.setProgram(qEnvironmentVariable("SLEW_BIN"));
    slew.setArguments({"--headless", "--config", example, "--rotctld-listen", "127.0.0.1:0"});
    slew.setProcessEnvironment(serviceEnvironment());
    slew.start();
    QByteArray out;
    QVERIFY(QTest::qWaitFor(
        [&] {
            out += slew.readAllStandardOutput();
            // The whole line: the port at its end may come in a later read.
            const qsizetype at = out.indexOf("rotctld listening on");
            return (at >= 0 && out.indexOf('\n', at) > at) || slew.state() == QProcess::NotRunning;
        },
        20000));
    QVERIFY2(slew.state() == QProcess::Running, slew.readAllStandardError().constData());
    const qsizetype at = out.indexOf("rotctld listening on");
    const QByteArray line = out.mid(at, out.indexOf('\n', at) - at);
    const quint16 port = quint16(line.mid(line.lastIndexOf(':') + 1).toUInt());
    QVERIFY2(port != 0 && port != 4533, line.constData());

    // It steers the simulator the file names (connect = sim:).
    QTcpSocket tracker;
    tracker.connectToHost(QHostAddress::LocalHost, port);
    QTRY_COMPARE(tracker.state(), QAbstractSocket::ConnectedState);
    QByteArray answer;
    QVERIFY(QTest::qWaitFor(
        [&] {
            tracker.write("p\n");
            QSignalSpy ready(&tracker, &QTcpSocket::readyRead);
            answer = ready.wait(2000) ? tracker.readAll() : QByteArray();
            return answer.count('\n') == 2;
        },
        20000));
    QVERIFY2(out.contains("sim:") || slew.readAllStandardOutput().contains("sim:"), out.constData());

    QSignalSpy finished(&slew, &QProcess::finished);
    slew.terminate();
    QVERIFY(finished.wait(10000));
    QCOMPARE(slew.exitCode(), 0);
}

void StationConfigTest::brokenFileIsRefusedWithItsLine()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("mast.conf");
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("connect = sim:\nrotctld_listen = 127.0.0.1:4533\n");
    file.close();

    QProcess slew;
    slew.setProgram(qEnvironmentVariable("SLEW_BIN"));
    slew.setArguments({"--headless", "--config", path});
    slew.setProcessEnvironment(serviceEnvironment());
    QSignalSpy finished(&slew, &QProcess::finished);
    slew.start();
    QVERIFY(finished.wait(10000));
    QCOMPARE(slew.exitCode(), 2);
    const QByteArray error = slew.readAllStandardError();
    QVERIFY2(error.contains(path.toUtf8() + ":2: unknown setting 'rotctld_listen'"), error.constData());
}

void StationConfigTest::manualPagesMatchHelp_data()
{
    QTest::addColumn<QString>("binary");
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("page");
    const QString slew = qEnvironmentVariable("SLEW_BIN"), sim = qEnvironmentVariable("SLEW_SIM_BIN");
    QTest::newRow("window") << slew << QStringList{"--help"} << "slew.1";
    QTest::newRow("headless") << slew << QStringList{"--headless", "--help"} << "slew.1";
    QTest::newRow("tune") << slew << QStringList{"--tune", "sim:", "--help"} << "slew.1";
    QTest::newRow("remote") << slew << QStringList{"--remote", "mqtt://localhost", "--help"} << "slew.1";
    QTest::newRow("slew-sim") << sim << QStringList{"--help"} << "slew-sim.1";
    QTest::newRow("slewctl") << qEnvironmentVariable("SLEWCTL_BIN") << QStringList{"--help"} << "slewctl.1";
}

void StationConfigTest::manualPagesMatchHelp()
{
    QFETCH(QString, binary);
    QFETCH(QStringList, arguments);
    QFETCH(QString, page);

    QFile manual(qEnvironmentVariable("SLEW_MAN_DIR") + u'/' + page);
    QVERIFY2(manual.open(QIODevice::ReadOnly), qPrintable(manual.fileName()));
    const QByteArray roff = manual.readAll();

    QProcess p;
    p.setProcessEnvironment(serviceEnvironment());
    QSignalSpy finished(&p, &QProcess::finished);
    p.start(binary, arguments);
    QVERIFY(finished.wait(10000));
    QCOMPARE(p.exitCode(), 0);
    const QList<QByteArray> help = p.readAllStandardOutput().split('\n');

    // Every long option --help lists is in the manual, and so is its text.
    int options = 0;
    for (const QByteArray &line : help) {
        // "  -h, --help   Displays…": the names fill the first column; a
        // wrapped description continues far further in.
        if (!line.startsWith("  -"))
            continue;
        const QByteArray names = line.mid(2, line.indexOf("  ", 2) - 2);
        for (const QByteArray &word : names.split(' ')) {
            if (!word.startsWith("--"))
                continue;
            QByteArray name = word;
            name.replace(",", "").replace("-", "\\-");
            if (const qsizetype equals = name.indexOf('='); equals > 0)
                name.truncate(equals);
            QVERIFY2(roff.contains("\\fB" + name + "\\fR"), (page + ": " + word).toUtf8().constData());
            ++options;
        }
    }
    QVERIFY2(options >= 5, QByteArray::number(options).constData());
}

QTEST_GUILESS_MAIN(StationConfigTest)
#include "tst_stationconfig.moc"
