// SPDX-License-Identifier: GPL-3.0-or-later
// The SPID firmware (spidfirmware.h) behind SimulatorFirmware: frames in,
// frames out, on the same rotator physics as the line dialects. Time is
// stepped on the rotator, so nothing here waits.
#include "sim/rotatormodels.h"
#include "sim/simulatedrotator.h"
#include "sim/simulatorfirmware.h"

#include "protocol/spidcodec.h"
#include "protocol/spidparser.h"

#include <QTest>

using namespace slew::sim;
using slew::protocol::Dialect;
namespace spid = slew::protocol::spid;

class TestSpidFirmware : public QObject {
    Q_OBJECT

    struct Bench {
        explicit Bench(Dialect d, SpidSettings settings = {}) : rotator(config()), firmware(rotator, counters, d)
        {
            firmware.configureSpid(settings);
        }
        static RotatorConfig config()
        {
            RotatorConfig c;
            applyRotatorModel(c, *findRotatorModel(u"satnogs"));
            return c;
        }
        SimulatedRotator rotator;
        FirmwareCounters counters;
        SimulatorFirmware firmware;
        QByteArray send(QByteArrayView bytes) { return firmware.receive(bytes); }
        QByteArray set(double az, double el, Dialect d) { return send(spid::encodeSet(az, el, d, 2, 2).bytes); }
    };

private slots:
    void rot2ProgAnswersStatusAndStopButNotSet()
    {
        Bench b(Dialect::Rot2Prog);
        QCOMPARE(b.send(spid::encodeStatus()), spid::encodeReply(0, 0, Dialect::Rot2Prog, 2, 2));
        QCOMPARE(b.set(10.5, 20.0, Dialect::Rot2Prog), QByteArray());
        b.rotator.advanceBy(10.0);
        QCOMPARE(b.send(spid::encodeStatus()), spid::encodeReply(10.5, 20.0, Dialect::Rot2Prog, 2, 2));
        QCOMPARE(b.send(spid::encodeStop()), spid::encodeReply(10.5, 20.0, Dialect::Rot2Prog, 2, 2));
        QCOMPARE(b.counters.rejected(), 0u);
        QCOMPARE(b.counters.commands, 1u);
    }

    void md01AnswersASetAtOnce()
    {
        Bench b(Dialect::Md01, {4, false});
        QCOMPARE(b.set(30.0, 40.0, Dialect::Md01), spid::encodeReply(0, 0, Dialect::Md01, 4, 4));
        b.rotator.advanceBy(10.0);
        QCOMPARE(b.send(spid::encodeStatus()), spid::encodeReply(30.0, 40.0, Dialect::Md01, 4, 4));
    }

    void rot1ProgIsAzimuthOnly()
    {
        Bench b(Dialect::Rot1Prog);
        b.rotator.pointElevation(15.0);
        QCOMPARE(b.send(spid::encodeSet(123.0, 0.0, Dialect::Rot1Prog).bytes), QByteArray());
        b.rotator.advanceBy(10.0);
        QCOMPARE(b.send(spid::encodeStatus()), QByteArray("\x57\x04\x08\x03\x20"));
        QCOMPARE(b.rotator.axis(Axis::Elevation).position(), 15.0); // the set left elevation alone
    }

    // With the quirk on, the MD-01 writes a text line ahead of each reply;
    // its first letter is the frame start byte, and a reader still finds the frame.
    void md01LogLinesPrecedeReplies()
    {
        Bench b(Dialect::Md01, {2, true});
        const QByteArray out = b.send(spid::encodeStatus());
        QVERIFY2(out.startsWith("W") && out.contains("\r\n"), out.constData());
        QVERIFY(out.endsWith(spid::encodeReply(0, 0, Dialect::Md01, 2, 2)));
        QStringList kinds;
        spid::Parser reader(Dialect::Md01);
        reader.feed(out, [&](const spid::Frame &f) { kinds << QString::number(int(f.kind)); });
        QCOMPARE(kinds, (QStringList{QString::number(int(spid::Frame::Kind::Text)),
                                     QString::number(int(spid::Frame::Kind::Reply))}));
    }

    void md01MoveDrivesAtTheManualSpeed()
    {
        Bench b(Dialect::Md01);
        b.set(100.0, 10.0, Dialect::Md01);
        b.rotator.advanceBy(10.0);
        QCOMPARE(b.send(spid::encodeMove(spid::MoveBit::Right | spid::MoveBit::Up, Dialect::Md01).bytes), QByteArray());
        b.rotator.advanceBy(1.0);
        QVERIFY(b.rotator.axis(Axis::Azimuth).position() > 110.0);
        QVERIFY(b.rotator.axis(Axis::Elevation).position() > 20.0);
        b.send(spid::encodeStop());
        const double stoppedAt = b.rotator.axis(Axis::Azimuth).position();
        b.rotator.advanceBy(5.0);
        QVERIFY(qAbs(b.rotator.axis(Axis::Azimuth).position() - stoppedAt) < 5.0);
    }

    void refusalsAreCountedAndNotAnswered()
    {
        Bench b(Dialect::Rot2Prog);
        // Inside the protocol's range but past this rotator's 450 degrees.
        QCOMPARE(b.set(500.0, 0.0, Dialect::Rot2Prog), QByteArray());
        QCOMPARE(b.counters.outOfLimits, 1u);
        // Outside the protocol's range: refused by the reader.
        QCOMPARE(b.send(QByteArray("\x57" "9999" "\x02" "0720" "\x02\x2F\x20", 13)), QByteArray());
        QCOMPARE(b.counters.outOfLimits, 2u);
        // A move is an MD-01 command only.
        QCOMPARE(b.send(spid::encodeMove(spid::MoveBit::Left, Dialect::Md01).bytes), QByteArray());
        QCOMPARE(b.counters.malformed, 1u);
        QCOMPARE(b.rotator.axis(Axis::Azimuth).position(), 0.0);
    }

    void garbageAndSplitFramesStillGetAnswers()
    {
        Bench b(Dialect::Rot2Prog);
        const QByteArray in = "\xFF\x57\x01" + spid::encodeStatus();
        QByteArray out;
        for (char c : in)
            out += b.send(QByteArrayView(&c, 1));
        QCOMPARE(out, spid::encodeReply(0, 0, Dialect::Rot2Prog, 2, 2));
        QCOMPARE(b.counters.malformed, 1u); // the three bytes, reported once
        QVERIFY(!b.firmware.hasUnfinishedLine());
        QCOMPARE(b.firmware.endLine(), QByteArray());
    }
};

QTEST_APPLESS_MAIN(TestSpidFirmware)
#include "tst_spidfirmware.moc"
