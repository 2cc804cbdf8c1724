// SPDX-License-Identifier: GPL-3.0-or-later
// Calibration offsets (the profile's azOffsetDeg and elOffsetDeg). The
// session reads and commands in the pointing frame, the controller's reading
// plus the offsets, and the wire carries the controller's own angles. Checked
// on the simulator's manual clock where offsets go wrong: across north
// (0/360) both ways, at the elevation stop of 90°, and for what stays the
// controller's own (raw lines, the park registers).

#include "../common/simulatorpump.h"
#include "linkschemes.h"
#include "protocol/parser.h"
#include "session/rotatorsession.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>

using slew::protocol::Message;
using slew::protocol::Op;
using slew::session::RotatorSession;

namespace {

// The set position in the bytes the session sent, as the controller reads it.
std::optional<QPointF> wireTarget(const QSignalSpy &sent)
{
    std::optional<double> az, el;
    slew::protocol::Parser parser(slew::protocol::Dialect::Easycomm3);
    for (const auto &args : sent)
        parser.feed(args.at(0).toByteArray(), [&](const Message &m) {
            if (m.op == Op::Azimuth && m.hasValue)
                az = m.value;
            if (m.op == Op::Elevation && m.hasValue)
                el = m.value;
        });
    if (!az || !el)
        return std::nullopt;
    return QPointF(*az, *el);
}

bool open(RotatorSession &s, double azOffset, double elOffset, double startAz = 100, double startEl = 20)
{
    slew::model::RotatorProfile profile;
    profile.azOffsetDeg = azOffset;
    profile.elOffsetDeg = elOffset;
    s.setProfile(profile);
    s.connectTo(QStringLiteral("sim:?clock=manual&model=satnogs&start_az=%1&start_el=%2").arg(startAz).arg(startEl));
    (new SimulatorPump(0.01, &s))->follow(&s);
    return runEventLoopUntil([&] { return s.capabilities().probed && s.hasPosition(); }, 10000);
}

bool arrives(RotatorSession &s, double az, double el)
{
    return runEventLoopUntil([&] {
        return std::abs(s.azimuth() - az) < 0.3 && std::abs(s.elevation() - el) < 0.3;
    }, 20000);
}

} // namespace

class CalibrationOffsetsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { slew::registerLinkSchemes(); }

    void readingsAndMovesAreInThePointingFrame()
    {
        RotatorSession s;
        QVERIFY(open(s, 3.0, -1.5)); // the controller reads 100°, 20°
        QVERIFY(std::abs(s.azimuth() - 103.0) < 0.05);
        QVERIFY(std::abs(s.elevation() - 18.5) < 0.05);
        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        QSignalSpy targets(&s, &RotatorSession::targetChanged);
        QVERIFY(s.gotoPosition(200, 45));
        QCOMPARE(wireTarget(sent), QPointF(197, 46.5));
        QCOMPARE(targets.last().at(0).toDouble(), 200.0);
        QCOMPARE(targets.last().at(1).toDouble(), 45.0);
        QVERIFY(arrives(s, 200, 45));
        // The gate's travel is the controller's, moved into the pointing frame.
        const slew::model::RotatorLimits l = s.moveGate().limits();
        QCOMPARE(l.azMin, 3.0);
        QCOMPARE(l.azMax, 363.0);
        QCOMPARE(l.elMin, -1.5);
        QCOMPARE(l.elMax, 88.5);
        // A relative move is the same either way.
        sent.clear();
        QVERIFY(s.moveBy(-10, 5));
        QVERIFY(std::abs(wireTarget(sent)->x() - 187) < 0.31 && std::abs(wireTarget(sent)->y() - 51.5) < 0.31);
    }

    void acrossNorth_data()
    {
        QTest::addColumn<double>("offset");
        QTest::addColumn<double>("asked");
        QTest::addColumn<double>("wire");
        // 0..360°: with +3° the antenna reaches 3°..363°, with -3° it reaches -3°..357°.
        QTest::newRow("+3, bearing 1 -> 358") << 3.0 << 1.0 << 358.0;
        QTest::newRow("+3, bearing 359 -> 356") << 3.0 << 359.0 << 356.0;
        QTest::newRow("-3, bearing 359 -> 2") << -3.0 << 359.0 << 2.0;
        QTest::newRow("-3, bearing 1 -> 4") << -3.0 << 1.0 << 4.0;
        QTest::newRow("+3, bearing 0 -> 357") << 3.0 << 0.0 << 357.0;
    }
    void acrossNorth()
    {
        QFETCH(double, offset);
        QFETCH(double, asked);
        QFETCH(double, wire);
        RotatorSession s;
        QVERIFY(open(s, offset, 0.0, 180, 10));
        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        QVERIFY(s.gotoPosition(asked, 30));
        QCOMPARE(wireTarget(sent)->x(), wire);
        // It arrives where it was asked to point: the reading plus the offset.
        QVERIFY(runEventLoopUntil([&] { return std::abs(std::remainder(s.azimuth() - asked, 360.0)) < 0.3; }, 30000));
        QCOMPARE(std::round(s.azimuth() - offset), wire);
    }

    void elevationEdge_data()
    {
        QTest::addColumn<double>("offset");
        QTest::addColumn<double>("asked");
        QTest::addColumn<bool>("allowed");
        QTest::addColumn<double>("wire");
        QTest::addColumn<double>("reached");
        // The controller's travel is 0..90°. An elevation inside it that the
        // offset puts just out of reach goes as far as the stop allows.
        QTest::newRow("-1, 90: to the stop, 89") << -1.0 << 90.0 << true << 90.0 << 89.0;
        QTest::newRow("+1, 0: to the stop, 1") << 1.0 << 0.0 << true << 0.0 << 1.0;
        QTest::newRow("+1, 91: reachable") << 1.0 << 91.0 << true << 90.0 << 91.0;
        QTest::newRow("+1, 92: past the stop") << 1.0 << 92.0 << false << 0.0 << 0.0;
        QTest::newRow("-1, 91: past the travel") << -1.0 << 91.0 << false << 0.0 << 0.0;
        QTest::newRow("-1, 89.5: reachable") << -1.0 << 89.5 << true << 90.0 << 89.0;
    }
    void elevationEdge()
    {
        QFETCH(double, offset);
        QFETCH(double, asked);
        QFETCH(bool, allowed);
        QFETCH(double, wire);
        QFETCH(double, reached);
        RotatorSession s;
        QVERIFY(open(s, 0.0, offset, 100, 45));
        s.setPolling(false);
        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        QSignalSpy refused(&s, &RotatorSession::moveRefused);
        const bool went = bool(s.gotoPosition(100, asked));
        QCOMPARE(went, allowed);
        if (!allowed) {
            QCOMPARE(refused.count(), 1);
            QVERIFY(sent.isEmpty());
            // The one-axis go-to and the planned path's go-to agree.
            QVERIFY(!s.gotoAxis(slew::session::Axis::Elevation, asked));
            QVERIFY(!s.gotoUnwrapped(100, asked));
            QVERIFY(sent.isEmpty());
            return;
        }
        QCOMPARE(wireTarget(sent)->y(), wire);
        s.setPolling(true);
        QVERIFY(arrives(s, 100, reached));
    }

    void rawLinesAndParkRegistersAreTheControllers()
    {
        RotatorSession s;
        QVERIFY(open(s, 3.0, 0.0)); // the antenna reaches 3..363 on a 0..360 controller
        s.setPolling(false);
        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        // Sent as typed, and checked as where the antenna would point.
        QVERIFY(s.sendRaw(QStringLiteral("AZ359.00")));
        QCOMPARE(sent.last().at(0).toByteArray(), QByteArray("AZ359.00\n"));
        QVERIFY(!s.sendRaw(QStringLiteral("AZ361.00"))); // past the controller's own stop
        QVERIFY(s.writeConfig(7, QStringLiteral("359")));
        QVERIFY(!s.writeConfig(7, QStringLiteral("361")));
        QVERIFY(!s.previewParkRegister(7, 361).allowed());
        QVERIFY(s.previewParkRegister(8, 90).allowed());
        // The park position the registers hold, as the antenna points there.
        QCOMPARE(s.parkAzimuth(), s.profile().parkAz + 3.0);
    }

    void anAzimuthOnlyControllerHasNoElevationOffset()
    {
        RotatorSession s;
        slew::model::RotatorProfile profile;
        profile.dialect = slew::protocol::Dialect::Micro2g;
        profile.elOffsetDeg = 2.0;
        s.setProfile(profile);
        QCOMPARE(s.elevationOffset(), 0.0);
        QCOMPARE(s.moveGate().limits().elMax, 0.0);
    }
};

QTEST_MAIN(CalibrationOffsetsTest)
#include "tst_calibrationoffsets.moc"
