// SPDX-License-Identifier: GPL-3.0-or-later
// Where PARK goes, as the session tells it. A controller with park registers
// (CW7/CW8) parks where they say, so the session reads them on connect,
// after the probe, and until then says the park is not known; a fresh
// profile's 0/90 must not pass for a controller's 0/0. A dialect without
// registers parks at the profile's position, known from the start.

#include "../common/simulatorpump.h"
#include "linkschemes.h"
#include "session/rotatorsession.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>

using slew::protocol::Dialect;
using slew::session::RotatorSession;

namespace {

int linesLike(const QSignalSpy &sent, const QByteArray &start)
{
    int n = 0;
    for (const auto &args : sent)
        n += args.at(0).toByteArray().startsWith(start) ? 1 : 0;
    return n;
}

} // namespace

class ParkRegistersTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { slew::registerLinkSchemes(); }

    void readOnConnectNotTakenFromTheProfile()
    {
        RotatorSession s;
        s.setProfile(profile(Dialect::SatNogs, 3.0));
        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        QSignalSpy targets(&s, &RotatorSession::targetChanged);
        bool knownWhenConnected = true;
        QString refusedWhenConnected;
        connect(&s, &RotatorSession::stateChanged, this, [&](RotatorSession::State state) {
            if (state != RotatorSession::State::Connected)
                return;
            knownWhenConnected = s.parkKnown();
            // Nothing read back yet, neither the registers nor where the
            // antenna stands: PARK does not go blind, and the profile's
            // guess is no target to show.
            refusedWhenConnected = s.park().refusal;
        });
        connectPumped(s, "sim:?clock=manual&dialect=satnogs"); // the simulator holds 0/0
        QVERIFY(s.hasParkRegisters());
        QVERIFY(!knownWhenConnected);
        QCOMPARE(refusedWhenConnected, QStringLiteral("no position read from the controller yet"));
        QCOMPARE(targets.count(), 0);
        QCOMPARE(linesLike(sent, "PARK"), 0);
        TRY_VERIFY(s.parkKnown());
        QCOMPARE(s.controllerParkAzimuth(), 0.0);
        QCOMPARE(s.controllerParkElevation(), 0.0);
        QCOMPARE(s.parkAzimuth(), 3.0); // in the pointing frame, as the plot shows it
        QCOMPARE(s.parkElevation(), 0.0);
        QCOMPARE(s.profile().parkEl, 90.0); // the profile is the operator's, untouched
        QCOMPARE(linesLike(sent, "CR 7"), 1);
        QCOMPARE(linesLike(sent, "CR 8"), 1);

        // A new connection may be another controller: read again.
        s.disconnectFromRotator();
        knownWhenConnected = true;
        connectPumped(s, "sim:?clock=manual&dialect=satnogs&park_el=30");
        QVERIFY(!knownWhenConnected);
        TRY_VERIFY(s.parkKnown());
        QCOMPARE(s.controllerParkElevation(), 30.0);
    }

    void aDialectWithoutRegistersParksAtTheProfiles()
    {
        RotatorSession s;
        s.setProfile(profile(Dialect::Gs232B, 3.0));
        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        QSignalSpy parkChanged(&s, &RotatorSession::parkChanged);
        QVERIFY(!s.hasParkRegisters());
        QVERIFY(s.parkKnown());
        connectPumped(s, "sim:?clock=manual&dialect=gs232b");
        TRY_VERIFY(s.hasPosition());
        QVERIFY(s.parkKnown());
        QCOMPARE(s.parkAzimuth(), 3.0);
        QCOMPARE(s.parkElevation(), 90.0);
        QCOMPARE(parkChanged.count(), 0);
        QCOMPARE(linesLike(sent, "CR"), 0);
    }

private:
    static slew::model::RotatorProfile profile(Dialect dialect, double azOffset)
    {
        slew::model::RotatorProfile p; // a fresh one: park 0/90
        p.dialect = dialect;
        p.pollHz = 10;
        p.azOffsetDeg = azOffset;
        return p;
    }

    static void connectPumped(RotatorSession &s, const char *uri)
    {
        // The session keeps the simulator's clock, which this pump moves on
        // from the event loop, through reconnects.
        if (!s.findChild<QObject *>(QLatin1String(SimulatorPump::kObjectName), Qt::FindDirectChildrenOnly))
            (new SimulatorPump(0.005, &s))->follow(&s);
        s.connectTo(QString::fromLatin1(uri));
        runEventLoopUntil([&] { return s.capabilities().probed; }, 10000);
    }
};

QTEST_MAIN(ParkRegistersTest)
#include "tst_parkregisters.moc"
