// SPDX-License-Identifier: GPL-3.0-or-later
// A session and the simulator with the XOR checksum (`checksum=1`) on and
// off: the same conversation works both ways; with it on every line is
// framed `*HH` in both directions, a damaged reply is refused (never taken
// as a position) and counted, three in a row raise the alarm, and a damaged
// or unframed command never moves the simulated rotator.

#include "../common/simulatorpump.h"
#include "linkschemes.h"
#include "session/rotatorsession.h"
#include "sim/simulator.h"
#include "sim/simulatorscheme.h"
#include "transport/linkfactory.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>
#include <memory>

using slew::session::RotatorSession;

class ChecksumLinkTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { slew::registerLinkSchemes(); }

    void sameConversationWithAndWithout_data()
    {
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<bool>("checksum");
        for (const char *d : {"easycomm3", "gs232b"}) {
            QTest::addRow("%s plain", d) << QString::fromLatin1(d) << false;
            QTest::addRow("%s checksum", d) << QString::fromLatin1(d) << true;
        }
    }

    void sameConversationWithAndWithout()
    {
        QFETCH(QString, dialect);
        QFETCH(bool, checksum);
        RotatorSession s;
        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        QSignalSpy received(&s, &RotatorSession::bytesReceived);
        slew::sim::Simulator *sim = open(s, dialect, checksum);
        QVERIFY(sim);
        QCOMPARE(s.checksumming(), checksum);

        QVERIFY(s.gotoPosition(30, 20));
        TRY_VERIFY_WITH_TIMEOUT(std::abs(s.azimuth() - 30) < 1.0 && std::abs(s.elevation() - 20) < 1.0, 15000);

        // Every line on the wire, both ways, carries the frame exactly when asked.
        for (const auto &args : sent)
            QCOMPARE(args.at(0).toByteArray().contains('*'), checksum);
        QByteArray all;
        for (const auto &args : received)
            all += args.at(0).toByteArray();
        QCOMPARE(all.contains('*'), checksum);
        QCOMPARE(s.checksumFailures(), 0);
        QCOMPARE(sim->counters().badChecksum, std::uint64_t(0));
    }

    void damagedRepliesAreRefusedCountedAndRaiseTheAlarm()
    {
        RotatorSession s;
        slew::sim::Simulator *sim = open(s, QStringLiteral("easycomm3"), true);
        QVERIFY(sim);
        QSignalSpy alarm(&s, &RotatorSession::badFramesAlarm);
        QSignalSpy positions(&s, &RotatorSession::positionChanged);

        // Every reply line gets one bit flipped from now on.
        slew::sim::LinkFaults faults = sim->linkFaults();
        faults.corruptRate = 1.0;
        sim->setLinkFaults(faults);
        const double azBefore = s.azimuth();
        TRY_VERIFY_WITH_TIMEOUT(alarm.count() >= 1, 10000);
        QCOMPARE(alarm.at(0).at(0).toBool(), true);
        QVERIFY(s.checksumFailures() >= RotatorSession::kBadFramesAlarm);
        for (const auto &args : positions)
            QVERIFY2(args.at(2).toBool(), "a fresh position was taken from a damaged reply");
        QCOMPARE(s.azimuth(), azBefore);

        // The line heals: the alarm clears and positions are fresh again.
        faults.corruptRate = 0.0;
        sim->setLinkFaults(faults);
        TRY_VERIFY_WITH_TIMEOUT(alarm.count() >= 2, 10000);
        QCOMPARE(alarm.last().at(0).toBool(), false);
        TRY_VERIFY_WITH_TIMEOUT(!s.positionStale() && !positions.isEmpty() && !positions.last().at(2).toBool(), 10000);
    }

    void damagedCommandsNeverMoveTheRotator()
    {
        RotatorSession s;
        slew::sim::Simulator *sim = open(s, QStringLiteral("easycomm3"), true);
        QVERIFY(sim);
        const auto commanded = [sim] { return sim->rotator().readRegister(10).value_or(-1); };
        const double before = commanded();
        // A set position with a wrong sum, one with none, and one with a
        // flipped payload bit (`AZ101` framed as `AZ100` was): none is read.
        const QByteArray good = slew::protocol::withChecksums("AZ100.00 EL40.00\n");
        QByteArray flipped = good;
        flipped[4] = '1';
        s.link()->device()->write("AZ100.00 EL40.00*00\n");
        s.link()->device()->write("AZ100.00 EL40.00\n");
        s.link()->device()->write(flipped);
        TRY_COMPARE(sim->counters().badChecksum, std::uint64_t(3));
        sim->advance(1.0);
        QCOMPARE(commanded(), before);
        // The same command framed right is carried out.
        s.link()->device()->write(good);
        TRY_COMPARE(commanded(), 100.0);
    }

    void checksumOnOtherLinksIsAnOption()
    {
        // Serial and TCP links take it as a URI item too; a bad value is
        // refused with a message and no link.
        QVERIFY(slew::transport::linkHintsFor(QStringLiteral("tcp://127.0.0.1:4533?checksum=1")).checksum);
        QVERIFY(!slew::transport::linkHintsFor(QStringLiteral("tcp://127.0.0.1:4533")).checksum);
        QVERIFY(slew::transport::linkHintsFor(QStringLiteral("serial:/dev/ttyS0?baud=9600&checksum=1")).checksum);
        const auto bad = slew::transport::createLink(QStringLiteral("tcp://127.0.0.1:4533?checksum=maybe"));
        QVERIFY(!bad.link);
        QVERIFY2(bad.error.contains(QStringLiteral("checksum")), qPrintable(bad.error));
        const auto badSim = slew::transport::createLink(QStringLiteral("sim:?checksum=maybe"));
        QVERIFY(!badSim.link);
    }

private:
    // A manual-clock simulator in `dialect`, probed and with a position.
    static slew::sim::Simulator *open(RotatorSession &s, const QString &dialect, bool checksum)
    {
        const QString uri = QStringLiteral("sim:?clock=manual&dialect=%1&start_az=10&start_el=5%2")
                                .arg(dialect, checksum ? QStringLiteral("&checksum=1") : QString());
        slew::model::RotatorProfile profile;
        profile.dialect = *slew::protocol::dialectFromName(dialect);
        s.setProfile(profile);
        s.connectTo(uri);
        // The session keeps the simulator's clock; this pump moves it on.
        (new SimulatorPump(0.005, &s))->follow(&s);
        if (!runEventLoopUntil([&] { return s.capabilities().probed && s.hasPosition(); }, 10000))
            return nullptr;
        return slew::sim::simulatorBehind(s.link());
    }
};

QTEST_MAIN(ChecksumLinkTest)
#include "tst_checksumlink.moc"
