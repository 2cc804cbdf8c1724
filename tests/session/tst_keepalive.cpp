// SPDX-License-Identifier: GPL-3.0-or-later
// The keep-alive `?` (GS-232, the easycom library): with polling paused the
// session sends it every Options::keepAliveMs, the simulator answers `OK`,
// and a link that stops answering is reported and the position goes stale.
// With polling on, nothing extra is sent: the polls prove the link.

#include "../common/simulatorpump.h"
#include "linkschemes.h"
#include "session/rotatorsession.h"
#include "sim/simulator.h"
#include "sim/simulatorscheme.h"

#include <QSignalSpy>
#include <QTest>

using slew::session::RotatorSession;

namespace {

int keepAlivesIn(const QSignalSpy &sent)
{
    int n = 0;
    for (const auto &args : sent)
        n += args.at(0).toByteArray() == "?\r" ? 1 : 0;
    return n;
}

} // namespace

class KeepAliveTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { slew::registerLinkSchemes(); }

    void onlyGs232HasIt()
    {
        using slew::protocol::Dialect;
        QVERIFY(slew::protocol::dialectSupports(Dialect::Gs232A, slew::protocol::Op::KeepAlive));
        QVERIFY(slew::protocol::dialectSupports(Dialect::Gs232B, slew::protocol::Op::KeepAlive));
        for (Dialect d : {Dialect::Easycomm1, Dialect::Easycomm2, Dialect::Easycomm3, Dialect::SatNogs, Dialect::Rotctld})
            QVERIFY(!slew::protocol::dialectSupports(d, slew::protocol::Op::KeepAlive));
    }

    void sentWhilePollingIsPausedAndAnswered()
    {
        RotatorSession s;
        QVERIFY(open(s));
        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        QSignalSpy received(&s, &RotatorSession::bytesReceived);
        QSignalSpy errors(&s, &RotatorSession::errorOccurred);
        s.setPolling(false);
        TRY_VERIFY(keepAlivesIn(sent) >= 3);
        QByteArray all;
        for (const auto &args : received)
            all += args.at(0).toByteArray();
        QVERIFY2(all.contains("OK\r\n"), all.constData());
        QCOMPARE(errors.count(), 0);
    }

    void aDeadLinkIsNoticedWhileIdle()
    {
        RotatorSession s;
        QVERIFY(open(s));
        QSignalSpy errors(&s, &RotatorSession::errorOccurred);
        s.setPolling(false);
        slew::sim::Simulator *sim = slew::sim::simulatorBehind(s.link());
        slew::sim::LinkFaults faults;
        faults.dropRate = 1.0; // every reply byte lost
        sim->setLinkFaults(faults);
        TRY_VERIFY_WITH_TIMEOUT(!errors.isEmpty(), 10000);
        QVERIFY2(errors.first().at(0).toString().contains(QStringLiteral("keep-alive")),
                 qPrintable(errors.first().at(0).toString()));
        QVERIFY(s.positionStale());
    }

    void notSentWhilePolling()
    {
        RotatorSession s;
        QVERIFY(open(s));
        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        QSignalSpy positions(&s, &RotatorSession::positionChanged);
        // Several keep-alive periods' worth of polls.
        TRY_VERIFY_WITH_TIMEOUT(positions.count() >= 8, 10000);
        QCOMPARE(keepAlivesIn(sent), 0);
    }

private:
    static bool open(RotatorSession &s)
    {
        RotatorSession::Options o = s.options();
        o.keepAliveMs = 150;
        s.setOptions(o);
        slew::model::RotatorProfile profile;
        profile.dialect = slew::protocol::Dialect::Gs232B;
        profile.pollHz = 10;
        s.setProfile(profile);
        s.connectTo(QStringLiteral("sim:?clock=manual&dialect=gs232b"));
        // The session keeps the simulator's clock (polls, keep-alives,
        // timeouts), which this pump moves on from the event loop.
        (new SimulatorPump(0.005, &s))->follow(&s);
        return runEventLoopUntil([&] { return s.capabilities().probed && s.hasPosition(); }, 10000);
    }
};

QTEST_MAIN(KeepAliveTest)
#include "tst_keepalive.moc"
