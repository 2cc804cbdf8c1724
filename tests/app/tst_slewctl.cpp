// SPDX-License-Identifier: GPL-3.0-or-later
// slewctl as a user runs it: the real binary against the built-in
// simulator, slew-sim over TCP and slew-sim's pseudo-terminal; exit codes
// for a refused move, a lost link and a bad argument; JSON for scripts; the
// prompt fed from a pipe; Ctrl-C during a watch and during a --wait move.

#include "../common/hamlibprocess.h"
#include "../sim/slewsimprocess.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QElapsedTimer>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>

namespace {

struct Run {
    int exitCode = -1;
    QString out;
    QString err;
};

Run slewctl(const QStringList &arguments, const QByteArray &input = {}, int timeoutMs = 60000)
{
    QProcess p;
    QSignalSpy finished(&p, &QProcess::finished);
    p.start(qEnvironmentVariable("SLEWCTL_BIN"), arguments);
    // Written before the process runs, the input waits in QProcess's buffer.
    if (!input.isEmpty())
        p.write(input);
    p.closeWriteChannel();
    if (!finished.wait(timeoutMs)) {
        p.kill();
        finished.wait(5000);
        return {};
    }
    Run r;
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

// "az 12.34 el 5.67" -> {12.34, 5.67}
std::pair<double, double> position(const QString &line)
{
    const QStringList w = line.split(u' ');
    return {w.value(1).toDouble(), w.value(3).toDouble()};
}

} // namespace

class SlewctlTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void everyLinkKind_data();
    void everyLinkKind();
    void refusedMoveSendsNothing();
    void exitCodesTellFailuresApart();
    void linkFailuresSayWhatTheWindowSays();
    void jsonIsOneObjectALine();
    void promptReadsAPipe();
    void interruptEndsAWatch();
    void interruptStopsAWaitingMove();
    void waitSaysWhereAMoveStoppedShort();
    void k3ngFirmwareIsReadAndItsRefusalIsSaidAtOnce();
    void satnogsFirmwareArrivesWhereItStops();
    void tunesARadioThroughRigctld();

private:
    QTemporaryDir m_dir;
    SlewSimProcess m_tcpSim;
    SlewSimProcess m_ptySim;
};

void SlewctlTest::initTestCase()
{
    QVERIFY(!qEnvironmentVariable("SLEWCTL_BIN").isEmpty());
    // The simulators run at 4x: slewctl's commands are under test, not the slews.
    QVERIFY2(m_tcpSim.start({"--listen", "127.0.0.1:0", "--time-scale", "4", "--log-received", m_dir.filePath("tcp.log")}),
             qPrintable(m_tcpSim.error()));
    QVERIFY2(m_ptySim.start({"--pty", m_dir.filePath("rotator"), "--dialect", "easycomm2", "--time-scale", "4"}),
             qPrintable(m_ptySim.error()));
}

void SlewctlTest::everyLinkKind_data()
{
    QTest::addColumn<QStringList>("link");
    QTest::newRow("sim:") << QStringList{"sim:?time_scale=4"};
    QTest::newRow("tcp") << QStringList{QStringLiteral("tcp://127.0.0.1:%1").arg(m_tcpSim.port())};
    QTest::newRow("pty") << QStringList{"--dialect", "easycomm2", "serial:" + m_dir.filePath("rotator")};
}

void SlewctlTest::everyLinkKind()
{
    QFETCH(QStringList, link);

    Run get = slewctl(link + QStringList{"get"});
    QCOMPARE(get.exitCode, 0);
    QVERIFY2(get.out.startsWith("az "), qPrintable(get.out + get.err));

    // A short move, waited for: it ends where it was sent, at rest, not on
    // its way through the arrival tolerance.
    const auto [az0, el0] = position(get.out.trimmed());
    const double az = az0 < 20 ? az0 + 8 : az0 - 8, el = el0 < 20 ? el0 + 4 : el0 - 4;
    Run move = slewctl(link + QStringList{"goto", QString::number(az), QString::number(el), "--wait"});
    QCOMPARE(move.exitCode, 0);
    const QStringList lines = move.out.trimmed().split(u'\n');
    QVERIFY2(lines.first().startsWith("moving to"), qPrintable(move.out));
    const auto [azEnd, elEnd] = position(lines.last());
    QVERIFY2(std::abs(azEnd - az) <= 0.25 && std::abs(elEnd - el) <= 0.25, qPrintable(move.out));

    // The controller's answer to a raw line.
    Run raw = slewctl(link + QStringList{"raw", "AZ EL"});
    QCOMPARE(raw.exitCode, 0);
    QVERIFY2(raw.out.startsWith("AZ"), qPrintable(raw.out + raw.err));

    Run stop = slewctl(link + QStringList{"stop"});
    QCOMPARE(stop.exitCode, 0);
    QCOMPARE(stop.out, QString("stopped\n"));
}

void SlewctlTest::refusedMoveSendsNothing()
{
    const QString link = QStringLiteral("tcp://127.0.0.1:%1").arg(m_tcpSim.port());
    auto received = [&] {
        QFile f(m_dir.filePath("tcp.log"));
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    };
    Run far = slewctl({link, "goto", "500", "10"});
    QCOMPARE(far.exitCode, 4);
    QVERIFY2(far.err.contains("outside"), qPrintable(far.err));
    Run raw = slewctl({link, "raw", "AZ500.0 EL10.0"});
    QCOMPARE(raw.exitCode, 4);
    Run reg = slewctl({link, "config", "set", "1", "0.9"});
    QCOMPARE(reg.exitCode, 0);
    QCOMPARE(reg.out, QString("CR1 0.900\n"));
    QVERIFY(!received().contains("AZ500"));
    QVERIFY(received().contains("CW1,0.9") || received().contains("CW1 0.9") || received().contains("CW1"));
}

void SlewctlTest::k3ngFirmwareIsReadAndItsRefusalIsSaidAtOnce()
{
    // slew-sim answering as K3NG's firmware does (docs/protocol.md,
    // "Controllers in the field"), at ten times the wall clock.
    const QString easycom = QStringLiteral("sim:?firmware=k3ng&dialect=easycomm2&time_scale=10&start_az=59.1&start_el=24.8");
    const Run got = slewctl({"--dialect", "easycomm2", easycom, "get"});
    QCOMPARE(got.exitCode, 0);
    QCOMPARE(got.out, QStringLiteral("az 59.10 el 24.80\n"));
    // It stops within its own 3° tolerance (2.3° short here): arrived, as
    // the URI names the firmware, not "stopped 2.30° from the target".
    const Run went = slewctl({"--dialect", "easycomm2", easycom, "goto", "94", "25", "--wait"});
    QVERIFY2(went.exitCode == 0, qPrintable(went.err));
    QVERIFY2(went.out.endsWith(QStringLiteral("az 91.70 el 25.00\n")), qPrintable(went.out));
    // Its Easycom has no PARK: with the firmware named, park is a go-to to
    // the profile's park position (0/90), and ends within its tolerance.
    const Run parked = slewctl({"--dialect", "easycomm2", easycom, "park", "--wait"});
    QVERIFY2(parked.exitCode == 0, qPrintable(parked.err));
    QVERIFY2(parked.out.endsWith(QStringLiteral("az 2.30 el 90.00\n")), qPrintable(parked.out));
    // Nor homing (RESET): its `?` ends the wait at once, with the reason,
    // and not after --timeout (600 s by default) as a move that never starts.
    QElapsedTimer clock;
    clock.start();
    const Run homed = slewctl({"--dialect", "easycomm2", easycom, "home", "--wait"});
    QCOMPARE(homed.exitCode, 4);
    QVERIFY2(homed.err.contains(QStringLiteral("the controller refused 'RESET' (it answered '?')")), qPrintable(homed.err));
    QVERIFY2(clock.elapsed() < 10000, qPrintable(QString::number(clock.elapsed())));
    // Its GS-232B runs the two reports together: read.
    const QString yaesuUri = QStringLiteral("sim:?firmware=k3ng&dialect=gs232b&time_scale=10&start_az=59&start_el=25");
    const Run yaesu = slewctl({"--dialect", "gs232b", yaesuUri, "get"});
    QCOMPARE(yaesu.exitCode, 0);
    QCOMPARE(yaesu.out, QStringLiteral("az 59.00 el 25.00\n"));
    // Its go-to ends inside its tolerance too (91.7°, reported in whole
    // degrees); GS-232 has no PARK, so park is the same go-to to 0/90.
    const Run yaesuWent = slewctl({"--dialect", "gs232b", yaesuUri, "goto", "94", "25", "--wait"});
    QVERIFY2(yaesuWent.exitCode == 0, qPrintable(yaesuWent.err));
    QVERIFY2(yaesuWent.out.endsWith(QStringLiteral("az 92.00 el 25.00\n")), qPrintable(yaesuWent.out));
    const Run yaesuStop = slewctl({"--dialect", "gs232b", yaesuUri, "stop"});
    QVERIFY2(yaesuStop.exitCode == 0, qPrintable(yaesuStop.err));
    const Run yaesuParked = slewctl({"--dialect", "gs232b", yaesuUri, "park", "--wait"});
    QVERIFY2(yaesuParked.exitCode == 0, qPrintable(yaesuParked.err));
    QVERIFY2(yaesuParked.out.endsWith(QStringLiteral("az 2.00 el 90.00\n")), qPrintable(yaesuParked.out));
}

void SlewctlTest::satnogsFirmwareArrivesWhereItStops()
{
    // slew-sim answering as the SatNOGS firmware v2.2 does, on a pty, with
    // the dialect named in the serial URI: GS4 for a whole move, no CR10 or
    // CR11, and a line sent within 9 ms of its reply lost (RS485).
    SlewSimProcess sim;
    QVERIFY2(sim.start({"--pty", m_dir.filePath("satnogs"), "--dialect", "satnogs", "--firmware", "satnogs",
                        "--time-scale", "4", "--start-az", "0", "--start-el", "0", "--log-received",
                        m_dir.filePath("satnogs.log")}),
             qPrintable(sim.error()));
    const QString link = "serial:" + m_dir.filePath("satnogs") + "?dialect=satnogs";
    const Run got = slewctl({link, "get"});
    QVERIFY2(got.exitCode == 0, qPrintable(got.err));
    QCOMPARE(got.out, QStringLiteral("az 0.00 el 0.00\n"));
    // Arrival is where it stopped, not where its status first lacked a moving bit.
    const Run went = slewctl({link, "goto", "49", "14", "--wait"});
    QVERIFY2(went.exitCode == 0, qPrintable(went.err + went.out));
    QVERIFY2(went.out.endsWith(QStringLiteral("az 49.00 el 14.00\n")), qPrintable(went.out));
    // Its park registers (CW7/CW8, 0/0) are read before PARK goes: the wait
    // ends at the park, not on the way.
    const Run parked = slewctl({link, "park", "--wait"});
    QVERIFY2(parked.exitCode == 0, qPrintable(parked.err + parked.out));
    QVERIFY2(parked.out.endsWith(QStringLiteral("az 0.00 el 0.00\n")), qPrintable(parked.out));
    // A command without --wait reaches the controller before slewctl goes,
    // though the line's turn-around holds it behind a poll's reply.
    auto received = [&] {
        QFile log(m_dir.filePath("satnogs.log"));
        return log.open(QIODevice::ReadOnly) ? log.readAll() : QByteArray();
    };
    const Run sent = slewctl({link, "goto", "120", "30"});
    QVERIFY2(sent.exitCode == 0, qPrintable(sent.err));
    QVERIFY2(received().contains("AZ120.0 EL30.0\n"), received().constData());
    const Run stopped = slewctl({link, "stop"});
    QVERIFY2(stopped.exitCode == 0, qPrintable(stopped.err));
    QVERIFY2(received().contains("SA SE\n"), received().constData());
    QCOMPARE(sim.stop(), 0);
    QVERIFY2(sim.standardError().contains(" 0 bytes lost"), sim.standardError().constData());
}

void SlewctlTest::exitCodesTellFailuresApart()
{
    QCOMPARE(slewctl({"sim:", "goto", "10"}).exitCode, 2);
    QCOMPARE(slewctl({"sim:", "fly"}).exitCode, 2);
    QCOMPARE(slewctl({}).exitCode, 2);
    QCOMPARE(slewctl({"--dialect", "morse", "sim:", "get"}).exitCode, 2);
    // Nothing listens on port 1.
    Run none = slewctl({"tcp://127.0.0.1:1", "get"});
    QCOMPARE(none.exitCode, 3);
    QVERIFY2(none.err.contains("127.0.0.1:1"), qPrintable(none.err));
    QCOMPARE(slewctl({"sim:", "goto", "0", "-30"}).exitCode, 4);
}

void SlewctlTest::linkFailuresSayWhatTheWindowSays()
{
    // A link kind Slew does not know: refused at once, in the window's
    // words, not "no answer" after the connect timeout.
    QElapsedTimer clock;
    clock.start();
    const Run bogus = slewctl({"bogus://x", "get"});
    QCOMPARE(bogus.exitCode, 3);
    QVERIFY2(bogus.err.contains("unknown link kind 'bogus'"), qPrintable(bogus.err));
    QVERIFY2(clock.elapsed() < 5000, "refused before any timeout");
    // The prompt refuses it the same way.
    const Run prompt = slewctl({"bogus://x"}, "get\n");
    QCOMPARE(prompt.exitCode, 3);
    QVERIFY2(prompt.err.contains("unknown link kind 'bogus'"), qPrintable(prompt.err));
    // A port that never opened was not "lost".
    const Run missing = slewctl({"serial:/dev/nonexistent-slew-port", "get"});
    QCOMPARE(missing.exitCode, 3);
    QVERIFY2(missing.err.contains("cannot connect: ") && missing.err.contains("No such file"), qPrintable(missing.err));
    QVERIFY2(!missing.err.contains("link lost"), qPrintable(missing.err));

    // --help tells a script what each exit code means.
    const Run help = slewctl({"--help"});
    QCOMPARE(help.exitCode, 0);
    QVERIFY2(help.out.contains("Exit status: 0 done") && help.out.contains("4 the move or line was refused"),
             qPrintable(help.out));
}

void SlewctlTest::jsonIsOneObjectALine()
{
    Run get = slewctl({"--json", "sim:?start_az=123&start_el=45", "get"});
    QCOMPARE(get.exitCode, 0);
    QJsonParseError error;
    const QJsonObject o = QJsonDocument::fromJson(get.out.toUtf8(), &error).object();
    QCOMPARE(error.error, QJsonParseError::NoError);
    QCOMPARE(o.value("event").toString(), QString("position"));
    QCOMPARE(o.value("az").toDouble(), 123.0);
    QCOMPARE(o.value("el").toDouble(), 45.0);

    Run refused = slewctl({"--json", "sim:", "goto", "400", "0"});
    QCOMPARE(refused.exitCode, 4);
    const QJsonObject e = QJsonDocument::fromJson(refused.err.toUtf8()).object();
    QCOMPARE(e.value("code").toInt(), 4);
    QVERIFY(e.value("error").toString().contains("outside"));
}

void SlewctlTest::promptReadsAPipe()
{
    Run r = slewctl({"sim:?start_az=10&start_el=20"}, "get\n\nraw 'VE'\nnonsense\nconfig get 2\nquit\nget\n");
    QCOMPARE(r.exitCode, 2); // the first failure's code: 'nonsense'; nothing after 'quit' runs
    const QStringList lines = r.out.trimmed().split(u'\n');
    QCOMPARE(lines.size(), 3);
    QCOMPARE(lines[0], QString("az 10.00 el 20.00"));
    QVERIFY2(lines[1].startsWith("VE"), qPrintable(r.out));
    QVERIFY2(lines[2].startsWith("CR2 "), qPrintable(r.out));
    QVERIFY(r.err.contains("unknown command 'nonsense'"));
}

void SlewctlTest::interruptEndsAWatch()
{
    QProcess p;
    p.start(qEnvironmentVariable("SLEWCTL_BIN"), {"sim:", "watch", "--interval", "0.1"});
    QByteArray out;
    QVERIFY(QTest::qWaitFor([&] { return (out += p.readAllStandardOutput()).count('\n') >= 3; }, 20000));
    QSignalSpy finished(&p, &QProcess::finished);
    ::kill(pid_t(p.processId()), SIGINT);
    QVERIFY(finished.wait(10000));
    QCOMPARE(p.exitCode(), 0);
}

void SlewctlTest::interruptStopsAWaitingMove()
{
    const QString link = QStringLiteral("tcp://127.0.0.1:%1").arg(m_tcpSim.port());
    QProcess p;
    p.start(qEnvironmentVariable("SLEWCTL_BIN"), {link, "goto", "300", "60", "--wait"});
    QByteArray out;
    QVERIFY(QTest::qWaitFor([&] { return (out += p.readAllStandardOutput()).contains("moving to"); }, 20000));
    auto received = [&] {
        QFile f(m_dir.filePath("tcp.log"));
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    };
    const qsizetype stopsBefore = received().count("SA SE");
    QSignalSpy finished(&p, &QProcess::finished);
    ::kill(pid_t(p.processId()), SIGINT);
    QVERIFY(finished.wait(10000));
    QCOMPARE(p.exitCode(), 1);
    QVERIFY(p.readAllStandardError().contains("interrupted; the rotator was stopped"));
    QTRY_VERIFY(received().count("SA SE") > stopsBefore);
}

void SlewctlTest::waitSaysWhereAMoveStoppedShort()
{
    // A --wait move that another client stops on the way ends there, saying
    // how far off it stopped, instead of waiting out its timeout.
    const QString link = QStringLiteral("tcp://127.0.0.1:%1").arg(m_tcpSim.port());
    QProcess p;
    QSignalSpy finished(&p, &QProcess::finished);
    const Run here = slewctl({link, "get"});
    const auto [az0, el0] = position(here.out.trimmed());
    const double az = az0 < 180 ? az0 + 120 : az0 - 120;
    p.start(qEnvironmentVariable("SLEWCTL_BIN"), {link, "goto", QString::number(az), "60", "--wait"});
    QByteArray out;
    QVERIFY(QTest::qWaitFor([&] { return (out += p.readAllStandardOutput()).contains("moving to"); }, 20000));
    // Let it get going, then stop it from elsewhere.
    QVERIFY(QTest::qWaitFor([&] { return std::abs(position(slewctl({link, "get"}).out.trimmed()).first - az0) > 2.0; },
                            20000));
    QCOMPARE(slewctl({link, "stop"}).exitCode, 0);
    QVERIFY(finished.wait(20000));
    QCOMPARE(p.exitCode(), 1);
    const QByteArray err = p.readAllStandardError();
    QVERIFY2(err.contains("stopped ") && err.contains("° from the target"), err.constData());
    out += p.readAllStandardOutput();
    QVERIFY2(out.trimmed().split('\n').last().startsWith("az "), out.constData());
}

void SlewctlTest::tunesARadioThroughRigctld()
{
    // `slewctl --radio`: one command to Hamlib's real rigctld (its dummy
    // rig), then what the radio holds, read back.
    QProcess rigctld;
    const quint16 port = startHamlibDaemon(rigctld, "rigctld", {"-m", "1"});
    QVERIFY(port);
    const QString uri = QStringLiteral("rigctld://127.0.0.1:%1").arg(port);
    Run r = slewctl({"--radio", uri, "freq", "145.8M"});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QCOMPARE(r.out.trimmed(), QString("receive 145.800 000 MHz"));
    r = slewctl({"--radio", uri, "split", "on"});
    QCOMPARE(r.exitCode, 0);
    // A new connection knows split is on, so the transmit side is read too.
    r = slewctl({"--json", "--radio", uri, "tx", "435.1M"});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    QCOMPARE(o.value("receive_hz").toDouble(), 145.8e6);
    QCOMPARE(o.value("transmit_hz").toDouble(), 435.1e6);
    r = slewctl({"--radio", uri, "mode", "usb"});
    QCOMPARE(r.exitCode, 0);
    // Words that make no command, and values that are no frequency or
    // mode, are refused before anything connects.
    for (const QStringList &bad : {QStringList{"freq", "nan"}, QStringList{"freq", "145.8"}, QStringList{"mode", "USB 2400"},
                                   QStringList{"split", "maybe"}, QStringList{"fly"}}) {
        r = slewctl(QStringList{"--radio", uri} + bad);
        QVERIFY2(r.exitCode == 2, qPrintable(bad.join(' ') + ": " + r.err));
        QVERIFY(r.err.startsWith("slewctl: "));
    }
    r = slewctl({"--radio", "nosuch://x"});
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains("unknown radio link kind 'nosuch'"), qPrintable(r.err));
    r = slewctl({"--radio", QStringLiteral("rigctld://127.0.0.1:%1").arg(freeTcpPort())});
    QCOMPARE(r.exitCode, 3); // no link
    QVERIFY(endHamlibDaemon(rigctld));
}

QTEST_GUILESS_MAIN(SlewctlTest)
#include "tst_slewctl.moc"
