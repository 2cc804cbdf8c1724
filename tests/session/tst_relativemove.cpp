// SPDX-License-Identifier: GPL-3.0-or-later
// GS-232's relative move `O+aaa-eee` (the easycom library's table) and the
// session's moveBy(): every one passes the limits gate before a byte is
// sent, the session's own goes out as an absolute W, a raw `O` line is
// checked against the last position read, and the simulator moves by it.
// All on the simulator's manual clock, pumped through the event loop.

#include "../common/simulatorpump.h"
#include "linkschemes.h"
#include "protocol/parser.h"
#include "session/rotatorsession.h"
#include "sim/simulator.h"

#include <QSignalSpy>
#include <QTest>

using slew::protocol::Dialect;
using slew::session::RotatorSession;

class RelativeMoveTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { slew::registerLinkSchemes(); }

    void sessionMoveGoesOutAsAbsolute_data() { dialects(); }
    void sessionMoveGoesOutAsAbsolute()
    {
        QFETCH(QString, dialect);
        RotatorSession s;
        QVERIFY(open(s, dialect));
        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        QVERIFY(s.moveBy(20, -3));
        QCOMPARE(sent.count(), 1);
        QCOMPARE(sent.at(0).at(0).toByteArray(), QByteArray("W120 007\r"));
        TRY_VERIFY_WITH_TIMEOUT(std::abs(s.azimuth() - 120) < 0.6 && std::abs(s.elevation() - 7) < 0.6, 20000);
    }

    void everyOutOfRangeRelativeMoveIsRefusedUnsent_data() { dialects(); }
    void everyOutOfRangeRelativeMoveIsRefusedUnsent()
    {
        QFETCH(QString, dialect);
        RotatorSession s;
        QVERIFY(open(s, dialect)); // at 100/10, limits 0..360 and 0..90
        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        QSignalSpy refused(&s, &RotatorSession::moveRefused);
        s.setPolling(false); // only what the paths below write reaches the link
        sent.clear();
        QVERIFY(!s.moveBy(-120, 0));  // azimuth -20
        QVERIFY(!s.moveBy(0, 85));    // elevation 95
        QVERIFY(!s.moveBy(qQNaN(), 0));
        for (const char *raw : {"O-120+000", "O+000+085", "O+270+000", "O+10", "Oops", "o+300-005"})
            QVERIFY2(!s.sendRaw(QString::fromLatin1(raw)), raw);
        QCOMPARE(refused.count(), 8); // NaN is refused as bad input, not by the gate
        for (const auto &args : sent)
            QVERIFY2(!isMove(args.at(0).toByteArray(), dialect), args.at(0).toByteArray().constData());
    }

    void rawRelativeMoveMovesTheSimulator()
    {
        RotatorSession s;
        QVERIFY(open(s, QStringLiteral("gs232b")));
        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        QVERIFY(s.sendRaw(QStringLiteral("O-030+015")));
        QVERIFY(!sent.isEmpty());
        QCOMPARE(sent.at(0).at(0).toByteArray(), QByteArray("O-030+015\n"));
        TRY_VERIFY_WITH_TIMEOUT(std::abs(s.azimuth() - 70) < 0.6 && std::abs(s.elevation() - 25) < 0.6, 20000);
    }

    void refusedWithoutAPosition()
    {
        // Nothing to add an offset to before the first position arrives.
        RotatorSession s;
        s.connectTo(QStringLiteral("sim:?clock=manual&dialect=gs232b"));
        QVERIFY(!s.hasPosition());
        QVERIFY(!s.moveBy(1, 1));
    }

private:
    static void dialects()
    {
        QTest::addColumn<QString>("dialect");
        QTest::newRow("gs232a") << QStringLiteral("gs232a");
        QTest::newRow("gs232b") << QStringLiteral("gs232b");
    }

    static bool isMove(const QByteArray &bytes, const QString &dialect)
    {
        using slew::protocol::Op;
        bool move = false;
        slew::protocol::Parser p(*slew::protocol::dialectFromName(dialect));
        p.feed(bytes + '\r', [&](const slew::protocol::Message &m) {
            move = move || m.op == Op::Offset || ((m.op == Op::Azimuth || m.op == Op::Elevation) && m.hasValue)
                || m.op == Op::MoveLeft || m.op == Op::MoveRight || m.op == Op::MoveUp || m.op == Op::MoveDown
                || m.op == Op::Invalid;
        });
        return move;
    }

    static bool open(RotatorSession &s, const QString &dialect)
    {
        slew::model::RotatorProfile profile;
        profile.dialect = *slew::protocol::dialectFromName(dialect);
        s.setProfile(profile);
        s.connectTo(QStringLiteral("sim:?clock=manual&model=satnogs&dialect=%1&start_az=100&start_el=10").arg(dialect));
        (new SimulatorPump(0.005, &s))->follow(&s);
        return runEventLoopUntil([&] { return s.capabilities().probed && s.hasPosition(); }, 10000)
            && std::abs(s.azimuth() - 100) < 0.6;
    }
};

QTEST_MAIN(RelativeMoveTest)
#include "tst_relativemove.moc"
