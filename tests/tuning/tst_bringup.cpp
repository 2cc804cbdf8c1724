// SPDX-License-Identifier: GPL-3.0-or-later
// The wizard's first steps without a window: baud-rate probing, dialect
// identification and homing with its verdicts, against the simulator.
#include "../common/simulatorpump.h"

#include "linkschemes.h"
#include "session/rotatorsession.h"
#include "sim/simulatorscheme.h"
#include "tuning/baudprobe.h"
#include "tuning/dialectidentifier.h"
#include "tuning/homingrun.h"

#include <QSignalSpy>
#include <QTest>

using namespace slew;
using session::RotatorSession;
using tuning::BaudProbe;
using tuning::DialectIdentifier;
using tuning::HomingRun;

class TestBringUp : public QObject {
    Q_OBJECT

    std::unique_ptr<RotatorSession> m_session;
    std::unique_ptr<SimulatorPump> m_pump;

    void connectTo(const QString &uri) { QVERIFY(connectPumped(uri, m_session, m_pump)); }
    sim::SimulatedRotator &rotator() { return sim::simulatorBehind(m_session->link())->rotator(); }

private slots:
    void initTestCase() { registerLinkSchemes(); }
    void cleanup()
    {
        m_pump.reset();
        m_session.reset();
    }

    void baudItemIsSetOrReplaced()
    {
        QCOMPARE(BaudProbe::withBaud(QStringLiteral("serial:/dev/ttyUSB0"), 9600),
                 QStringLiteral("serial:/dev/ttyUSB0?baud=9600"));
        QCOMPARE(BaudProbe::withBaud(QStringLiteral("serial:/dev/ttyUSB0?baud=1200&parity=none"), 115200),
                 QStringLiteral("serial:/dev/ttyUSB0?parity=none&baud=115200"));
        QVERIFY(BaudProbe::isSerial(QStringLiteral("serial:/dev/ttyS0")));
        QVERIFY(!BaudProbe::isSerial(QStringLiteral("tcp://localhost:4533")));
    }

    void probeReportsEveryRate()
    {
        BaudProbe probe;
        QSignalSpy done(&probe, &BaudProbe::finished);
        QVERIFY(!probe.start(QStringLiteral("  ")));
        QVERIFY(probe.start(QStringLiteral("serial:/dev/slew-no-such-port")));
        QVERIFY(done.wait(20000));
        QCOMPARE(done.front().front().toBool(), false);
        QCOMPARE(probe.results().size(), 5);
        QList<qint32> rates;
        for (const auto &r : probe.results())
            rates.append(r.baud);
        for (qint32 rate : {9600, 19200, 38400, 57600, 115200})
            QVERIFY(rates.contains(rate));
        for (const auto &r : probe.results())
            QVERIFY(!r.answered && !r.detail.isEmpty());

        QVERIFY(probe.start(QStringLiteral("sim:")));
        QVERIFY(done.wait(5000));
        QCOMPARE(probe.results().size(), 1);
        QVERIFY(probe.results().front().answered);
        QCOMPARE(probe.answeringUri(), QStringLiteral("sim:"));
    }

    void identifiesTheDialect_data()
    {
        QTest::addColumn<QString>("uri");
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<QString>("firmware");
        QTest::newRow("easycomm3") << "sim:" << "easycomm3" << "generic";
        QTest::newRow("satnogs") << "sim:?dialect=satnogs" << "satnogs" << "satnogs";
        QTest::newRow("SatNOGS firmware") << "sim:?dialect=satnogs&firmware=satnogs" << "satnogs" << "satnogs";
        QTest::newRow("easycomm2") << "sim:?dialect=easycomm2" << "easycomm2" << "generic";
        // K3NG's controllers: Easycom says `?` to what it lacks; its Yaesu
        // emulation (the default) is asked once no Easycomm got a position,
        // and runs its report together (`AZ=059EL=025`) where a Yaesu does not.
        QTest::newRow("K3NG Easycom") << "sim:?dialect=easycomm2&firmware=k3ng" << "easycomm2" << "k3ng";
        QTest::newRow("K3NG GS-232B") << "sim:?dialect=gs232b&firmware=k3ng" << "gs232b" << "k3ng";
        QTest::newRow("gs232b") << "sim:?dialect=gs232b" << "gs232b" << "generic";
        // SPID by its binary answers: after every line protocol failed, or
        // first on a line at a SPID rate. An MD-01/02 answers as a Rot2Prog.
        QTest::newRow("rot2prog") << "sim:?dialect=rot2prog" << "rot2prog" << "generic";
        QTest::newRow("rot2prog at 600 baud") << "sim:?dialect=rot2prog&baud=600&time_scale=20" << "rot2prog" << "generic";
        QTest::newRow("rot1prog at 1200 baud") << "sim:?dialect=rot1prog&baud=1200&time_scale=20" << "rot1prog" << "generic";
        QTest::newRow("md01") << "sim:?dialect=md01" << "rot2prog" << "generic";
    }
    void identifiesTheDialect()
    {
        QFETCH(QString, uri);
        QFETCH(QString, dialect);
        DialectIdentifier id;
        QSignalSpy done(&id, &DialectIdentifier::finished);
        QVERIFY(id.start(uri));
        QVERIFY(done.wait(30000));
        QVERIFY(id.best());
        for (const auto &r : id.results())
            qInfo().noquote() << r.describe() << r.score;
        QCOMPARE(protocol::dialectName(id.best()->dialect), dialect);
        QFETCH(QString, firmware);
        QCOMPARE(protocol::firmwareName(id.best()->firmware), firmware);
        if (firmware == QLatin1String("k3ng"))
            QVERIFY(id.best()->describe().contains(QStringLiteral("K3NG rotator controller")));
        if (dialect == QLatin1String("rot2prog"))
            QVERIFY(id.best()->describe().contains(QStringLiteral("choose md01")));
    }

    void homesAndSaysSo()
    {
        connectTo(QStringLiteral("sim:?clock=manual&unsolicited=1&start_az=12&start_el=6"));
        if (QTest::currentTestFailed())
            return;
        HomingRun homing(m_session.get());
        QSignalSpy ok(&homing, &HomingRun::succeeded);
        QSignalSpy failed(&homing, &HomingRun::failed);
        QVERIFY(homing.start(60));
        TRY_VERIFY_WITH_TIMEOUT(ok.count() + failed.count() == 1, 20000);
        QCOMPARE(ok.count(), 1);
        QVERIFY(std::fabs(m_session->azimuth()) < 0.5);
    }

    void missingEndStopIsAHomingError()
    {
        connectTo(QStringLiteral("sim:?clock=manual&unsolicited=1&start_az=12&start_el=6&no_endstop=az"));
        if (QTest::currentTestFailed())
            return;
        HomingRun homing(m_session.get());
        QSignalSpy failed(&homing, &HomingRun::failed);
        QVERIFY(homing.start(120));
        TRY_COMPARE_WITH_TIMEOUT(failed.count(), 1, 20000);
        const QString why = failed.front().front().toString();
        QVERIFY2(why.contains(QStringLiteral("homing error")), qPrintable(why));
        QVERIFY2(why.contains(QStringLiteral("end stop")), qPrintable(why));
    }

    void cancelStopsTheRotator()
    {
        connectTo(QStringLiteral("sim:?clock=manual&unsolicited=1&start_az=40&start_el=20"));
        if (QTest::currentTestFailed())
            return;
        HomingRun homing(m_session.get());
        QSignalSpy cancelled(&homing, &HomingRun::cancelled);
        QSignalSpy failed(&homing, &HomingRun::failed);
        QSignalSpy ok(&homing, &HomingRun::succeeded);
        // Cancel part way, from the position report itself: the stepped
        // clock would finish the homing between two polls of a QTRY.
        connect(m_session.get(), &RotatorSession::positionChanged, &homing, [&](double az, double, bool) {
            if (az < 38.0 && homing.isRunning())
                homing.cancel();
        });
        QVERIFY(homing.start(120));
        TRY_COMPARE_WITH_TIMEOUT(cancelled.count() + failed.count() + ok.count(), 1, 20000);
        QVERIFY2(failed.isEmpty(), failed.isEmpty() ? "" : qPrintable(failed.front().front().toString()));
        QCOMPARE(cancelled.count(), 1);
        TRY_VERIFY_WITH_TIMEOUT(rotator().axis(sim::Axis::Azimuth).isStopped(), 5000);
        QVERIFY(rotator().axis(sim::Axis::Elevation).isStopped());
        QVERIFY(m_session->azimuth() > 10.0);
    }
};

QTEST_GUILESS_MAIN(TestBringUp)
#include "tst_bringup.moc"
