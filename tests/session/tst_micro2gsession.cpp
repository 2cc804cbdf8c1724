// SPDX-License-Identifier: GPL-3.0-or-later
// A RotatorSession driving one rotor of the simulated Micro-2g controller:
// in process on the simulator's manual clock (`sim:?dialect=micro2g&rotor=2`),
// and against the real slew-sim over TCP, whose --state-file keeps the
// controller's settings across a restart.

#include "../common/simulatorpump.h"
#include "../sim/slewsimprocess.h"
#include "linkschemes.h"
#include "sim/simulator.h"
#include "sim/simulatoroptions.h"
#include "session/micro2gcalibration.h"
#include "session/rotatorsession.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using slew::session::Axis;
using slew::session::Micro2gCalibration;
using slew::session::RotatorSession;

class Micro2gSessionTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { slew::registerLinkSchemes(); }

    void drivesOneRotorOnTheManualClock()
    {
        RotatorSession s;
        QVERIFY(open(s, QStringLiteral("sim:?clock=manual&dialect=micro2g&rotor=2")));
        QCOMPARE(s.rotor(), 2);
        slew::sim::Simulator *sim = slew::sim::simulatorBehind(s.link());
        QVERIFY(sim);
        // The probe asked `?` and the controller named itself.
        QVERIFY2(s.version().startsWith(QStringLiteral("Micro-2g")), qPrintable(s.version()));
        QCOMPARE(s.azimuth(), 0.0); // the north stop: the default calibration's left end
        QCOMPARE(s.elevation(), 0.0);

        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        QVERIFY(s.gotoPosition(35, 0));
        QCOMPARE(sent.first().at(0).toByteArray(), QByteArray("2\rM035\r"));
        // It stops within its tolerance (20 counts, about 6 degrees) of 35.
        TRY_VERIFY_WITH_TIMEOUT(sim->micro2g().drive(2) == slew::sim::Micro2gController::Drive::Off
                                     && std::abs(s.azimuth() - 35) <= 6.5 && !s.positionStale(),
                                 20000);
        QCOMPARE(sim->micro2g().travel(1), 0.0); // the other rotors stayed where they were
        QVERIFY(wrote(sent, "C2\r"));           // the poll names the rotor

        // A stop names it too; the elevation alone has nothing to stop.
        QVERIFY(s.gotoPosition(120, 0));
        QVERIFY(s.stop(QStringLiteral("the test")));
        QVERIFY(wrote(sent, "S2\r"));
        QVERIFY(!s.stop(QStringLiteral("the test"), slew::session::Axes::Elevation));
    }

    void refusesWhatTheControllerCannotDo()
    {
        RotatorSession s;
        QVERIFY(open(s, QStringLiteral("sim:?clock=manual&dialect=micro2g")));
        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        QSignalSpy refusedMoves(&s, &RotatorSession::moveRefused);
        QVERIFY(!s.gotoPosition(100, 20));              // no elevation axis: the gate says so
        QVERIFY(!s.gotoAxis(Axis::Elevation, 10));
        QVERIFY(!s.moveBy(0, 5));
        QCOMPARE(refusedMoves.count(), 3);
        QVERIFY(!s.readConfig(1));                      // no registers
        QVERIFY(!s.writeConfig(1, QStringLiteral("2")));
        QVERIFY(!s.home());
        QVERIFY(!s.sendRaw(QStringLiteral("M400")));    // not a bearing
        for (const auto &args : sent) {
            const QByteArray bytes = args.at(0).toByteArray();
            QVERIFY2(bytes == "C\r" || bytes == "?\r", bytes.constData()); // polls only
        }
        // Without a rotor on the URI, the default rotor's forms.
        QVERIFY(s.gotoAxis(Axis::Azimuth, 90));
        QCOMPARE(sent.last().at(0).toByteArray(), QByteArray("M090\r"));
        // No speeds and no bare moves: a jog is set-position legs of under
        // half a turn (session/joglegs.h), the bearing the short way, which
        // is the way pressed; the release's stop ends it.
        QVERIFY(s.stop(QStringLiteral("the test")));
        const double from = s.azimuth();
        QVERIFY(s.moveAxis(Axis::Azimuth, 3.0));
        const QByteArray leg = sent.last().at(0).toByteArray();
        QVERIFY2(leg.startsWith('M') && leg.endsWith('\r'), leg.constData());
        const int to = leg.mid(1, 3).toInt();
        QVERIFY2(std::fmod(to - from + 360.0, 360.0) > 1.0 && std::fmod(to - from + 360.0, 360.0) <= 170.5,
                 leg.constData());
        QVERIFY(s.stop(QStringLiteral("the test")));
    }

    void asksForAndSetsTheCalibrationThroughTheQueue()
    {
        RotatorSession s;
        QVERIFY(open(s, QStringLiteral("sim:?clock=manual&dialect=micro2g&rotor=2")));
        slew::sim::Simulator *sim = slew::sim::simulatorBehind(s.link());
        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        QSignalSpy calibrations(s.micro2g(), &Micro2gCalibration::calibrationReceived);
        QSignalSpy readings(s.micro2g(), &Micro2gCalibration::adcReadingReceived);
        QSignalSpy failed(s.micro2g(), &Micro2gCalibration::calibrationFailed);

        // `Z` lists every rotor; each line is handed on.
        QVERIFY(s.micro2g()->request(2));
        TRY_COMPARE(calibrations.count(), 4);
        QCOMPARE(calibrations.at(1).at(0).toInt(), 2);
        QCOMPARE(calibrations.at(1).at(1).value<slew::protocol::Micro2gCalibration>(),
                 (slew::protocol::Micro2gCalibration{2, 3990, 0, 2440, 90, 450}));
        QVERIFY(s.micro2g()->requestAdcReadings());
        TRY_COMPARE(readings.count(), 4);
        QCOMPARE(readings.at(1).at(0).toInt(), 2);
        QCOMPARE(readings.at(1).at(1).toInt(), 3990);

        // A setting goes out with `Z` after it on one request, and what the
        // controller now holds comes back.
        sent.clear();
        calibrations.clear();
        QVERIFY(s.micro2g()->set(2, Micro2gCalibration::Point::LeftStop, 180));
        TRY_VERIFY(calibrations.count() == 4);
        QVERIFY(wrote(sent, "Z2L 180\rZ\r"));
        QCOMPARE(sim->micro2g().calibration(2).leftBearing, 180.0);
        QCOMPARE(failed.count(), 0);

        // Refused before a byte: out of range, or another rotor number.
        sent.clear();
        QVERIFY(!s.micro2g()->set(2, Micro2gCalibration::Point::DegreeRange, 600));
        QVERIFY(!s.micro2g()->set(2, Micro2gCalibration::Point::RightStop, 360));
        QVERIFY(!s.micro2g()->set(5, Micro2gCalibration::Point::LeftStop, 0));
        QVERIFY(!s.micro2g()->request(0));
        for (const auto &args : sent)
            QVERIFY2(!args.at(0).toByteArray().startsWith('Z'), args.at(0).toByteArray().constData());

        // Refused by the controller: the right stop on the left stop's
        // reading. The request fails with the controller's words, and its
        // calibration is as it was.
        QVERIFY(s.micro2g()->set(2, Micro2gCalibration::Point::RightStop, 270));
        TRY_COMPARE(failed.count(), 1);
        QCOMPARE(failed.first().at(0).toInt(), 2);
        QVERIFY2(failed.first().at(1).toString().contains(QStringLiteral("10 counts")),
                 qPrintable(failed.first().at(1).toString()));
        QCOMPARE(sim->micro2g().calibration(2).rightAdc, 2440);
        QCOMPARE(sim->micro2g().calibration(2).rightBearing, 90.0);
        // Polling goes on as before.
        const int polls = int(sent.count());
        TRY_VERIFY(sent.count() > polls + 2 && !s.positionStale());
    }

    void slewSimOverTcpKeepsItsStateFile()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString state = dir.filePath(QStringLiteral("micro2g.json"));
        const QStringList args{"--listen", "127.0.0.1:0", "--dialect", "micro2g", "--state-file", state, "--time-scale", "4"};
        {
            SlewSimProcess sim;
            QVERIFY2(sim.start(args), qPrintable(sim.error()));
            RotatorSession s;
            QVERIFY(open(s, QStringLiteral("tcp://127.0.0.1:%1?rotor=3").arg(sim.port()), false));
            QSignalSpy received(&s, &RotatorSession::bytesReceived);
            QVERIFY(s.sendRaw(QStringLiteral("T3 35")));      // rotor 3's tolerance
            QVERIFY(s.gotoPosition(45, 0));
            TRY_VERIFY_WITH_TIMEOUT(s.azimuth() > 20, 15000); // turning, at 6 degrees a second
            QVERIFY(s.sendRaw(QStringLiteral("T")));
            TRY_VERIFY(joined(received).contains("T1=20 T2=20 T3=35 T4=20"));
            s.disconnectFromRotator();
            QCOMPARE(sim.stop(), 0);
        }
        QVERIFY(QFile::exists(state));
        // A new run, the same file: the tolerance is still there.
        SlewSimProcess sim;
        QVERIFY2(sim.start(args), qPrintable(sim.error()));
        RotatorSession s;
        QVERIFY(open(s, QStringLiteral("tcp://127.0.0.1:%1?rotor=3").arg(sim.port()), false));
        QSignalSpy received(&s, &RotatorSession::bytesReceived);
        QVERIFY(s.sendRaw(QStringLiteral("T")));
        TRY_VERIFY(joined(received).contains("T3=35"));
        QCOMPARE(sim.stop(), 0);

        // A file that is not a state is refused at start, naming the file.
        QFile bad(state);
        QVERIFY(bad.open(QIODevice::WriteOnly | QIODevice::Truncate));
        bad.write("{\"rotors\": 7}");
        bad.close();
        SlewSimProcess refused;
        QVERIFY(!refused.start(args));
        QVERIFY2(refused.error().contains(QStringLiteral("micro2g.json")), qPrintable(refused.error()));
    }

    void aStateFileThatCannotBeWrittenIsSaid()
    {
        // Nowhere to write: the directory does not exist. A missing file at
        // start is a fresh controller, not an error.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("gone/micro2g.json"));
        slew::sim::SimulatorOptions options;
        QVERIFY(slew::sim::applySimulatorOption(options, u"dialect", u"micro2g").isEmpty());
        QVERIFY(slew::sim::applySimulatorOption(options, u"clock", u"manual").isEmpty());
        QVERIFY(slew::sim::applySimulatorOption(options, u"state_file", path).isEmpty());
        slew::sim::Simulator sim(options);
        sim.micro2g();
        QCOMPARE(sim.stateFileError(), QString());
        QSignalSpy failed(&sim, &slew::sim::Simulator::stateFileFailed);
        sim.handleMicro2g(QStringLiteral("T1 30")); // a setting changes: it is written
        QCOMPARE(failed.count(), 1);
        QVERIFY2(failed.first().at(0).toString().contains(path), qPrintable(failed.first().at(0).toString()));
        QCOMPARE(sim.micro2g().tolerance(1), 30); // kept while running all the same
        sim.handleMicro2g(QStringLiteral("C1"));   // a poll changes nothing, writes nothing
        QCOMPARE(failed.count(), 1);
    }

    void slewSimOverItsPty()
    {
        // The controller's own line settings: 9600 8N1, paced by slew-sim.
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("micro2g"));
        SlewSimProcess sim;
        QVERIFY2(sim.start({"--pty", path, "--dialect", "micro2g", "--baud", "9600", "--time-scale", "4"}), qPrintable(sim.error()));
        RotatorSession s;
        QVERIFY(open(s, QStringLiteral("serial:%1?baud=9600&rotor=4").arg(path), false));
        QVERIFY2(s.version().startsWith(QStringLiteral("Micro-2g")), qPrintable(s.version()));
        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        QVERIFY(s.gotoPosition(30, 0));
        QCOMPARE(sent.first().at(0).toByteArray(), QByteArray("4\rM030\r"));
        TRY_VERIFY_WITH_TIMEOUT(s.azimuth() > 10, 15000); // rotor 4 turns, at 6 degrees a second
        QVERIFY(wrote(sent, "C4\r"));
        QVERIFY(s.stop(QStringLiteral("the test")));
        s.disconnectFromRotator();
        QCOMPARE(sim.stop(), 0);
    }

private:
    static bool open(RotatorSession &s, const QString &uri, bool manualClock = true)
    {
        slew::model::RotatorProfile profile;
        profile.dialect = slew::protocol::Dialect::Micro2g;
        s.setProfile(profile);
        s.connectTo(uri);
        if (manualClock)
            (new SimulatorPump(0.005, &s))->follow(&s);
        return runEventLoopUntil([&] { return s.capabilities().probed && s.hasPosition(); }, 10000);
    }

    static bool wrote(const QSignalSpy &sent, const QByteArray &bytes)
    {
        for (const auto &args : sent) {
            if (args.at(0).toByteArray() == bytes)
                return true;
        }
        return false;
    }

    static QByteArray joined(const QSignalSpy &spy)
    {
        QByteArray all;
        for (const auto &args : spy)
            all += args.at(0).toByteArray();
        return all;
    }
};

QTEST_MAIN(Micro2gSessionTest)
#include "tst_micro2gsession.moc"
