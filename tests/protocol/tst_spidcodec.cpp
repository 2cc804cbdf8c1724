// SPDX-License-Identifier: GPL-3.0-or-later
// The SPID codec and its incremental reader (spidcodec.h, spidparser.h).
// The byte vectors are what Hamlib's SPID backend (rotators/spid/spid.c,
// models 901 Rot2Prog, 902 Rot1Prog, 903 MD-01/02) writes and reads: a set
// is PH × (360 + az) in four ASCII digits, status and stop are zero frames
// with K 0x1F and 0x0F, a reply carries tenths as raw digits.

#include "messagedump.h"

#include "protocol/dialect.h"
#include "protocol/encoder.h"
#include "protocol/parser.h"
#include "protocol/spidcodec.h"
#include "protocol/spidparser.h"

#include <QRandomGenerator>
#include <QTest>

#include <vector>

using namespace slew::protocol;
using spid::Frame;

namespace {

QByteArray bytes(std::initializer_list<int> values)
{
    QByteArray b;
    for (int v : values)
        b += char(v);
    return b;
}

// Hamlib's example position: az 10.5, el 20.0 at PH = PV = 2.
const QByteArray kReply = bytes({0x57, 3, 7, 0, 5, 2, 3, 8, 0, 0, 2, 0x20});

// One line per frame, so tests can compare lists of text.
QString dump(const Frame &f)
{
    switch (f.kind) {
    case Frame::Kind::Reply:
        return QStringLiteral("reply %1 %2 /%3/%4").arg(f.azimuth).arg(f.elevation).arg(f.azimuthPulses).arg(f.elevationPulses);
    case Frame::Kind::Command:
        return QStringLiteral("command %1 %2 %3 move%4")
            .arg(int(f.command), 2, 16, QLatin1Char('0'))
            .arg(f.azimuth)
            .arg(f.elevation)
            .arg(f.moveDirections);
    case Frame::Kind::Text:
        return QStringLiteral("text '%1'%2").arg(QString::fromLatin1(f.text.view().toByteArray()), f.reason ? " cut" : "");
    case Frame::Kind::Skipped: return QStringLiteral("skipped %1").arg(f.skipped);
    case Frame::Kind::Refused: return QStringLiteral("refused: %1").arg(QString::fromLatin1(f.reason));
    }
    return {};
}

QStringList read(Dialect d, QByteArrayView in, bool flush = true)
{
    QStringList out;
    spid::Parser p(d);
    auto keep = [&](const Frame &f) { out << dump(f); };
    p.feed(in, keep);
    if (flush)
        p.flush(keep);
    return out;
}

} // namespace

class SpidCodecTest : public QObject {
    Q_OBJECT
private slots:
    void named()
    {
        QCOMPARE(dialectFromName(u"rot2prog"), std::optional<Dialect>(Dialect::Rot2Prog));
        QCOMPARE(dialectFromName(u"ROT1PROG"), std::optional<Dialect>(Dialect::Rot1Prog));
        QCOMPARE(dialectFromName(u"md01"), std::optional<Dialect>(Dialect::Md01));
        QVERIFY(dialectNameList().endsWith(QLatin1String("rot2prog, rot1prog, md01")));
        for (Dialect d : {Dialect::Rot2Prog, Dialect::Rot1Prog, Dialect::Md01})
            QVERIFY(isSpid(d));
        QVERIFY(!isSpid(Dialect::Gs232B));
        QVERIFY(isAzimuthOnly(Dialect::Rot1Prog));
        QVERIFY(!isAzimuthOnly(Dialect::Rot2Prog));
    }

    void supportsSetStatusStopOnly()
    {
        for (Dialect d : {Dialect::Rot2Prog, Dialect::Md01}) {
            for (Op op : {Op::Azimuth, Op::Elevation, Op::StopAzimuth, Op::StopElevation})
                QVERIFY2(dialectSupports(d, op), describe(op));
        }
        QVERIFY(dialectSupports(Dialect::Rot1Prog, Op::Azimuth));
        QVERIFY(dialectSupports(Dialect::Rot1Prog, Op::StopAzimuth));
        QVERIFY(!dialectSupports(Dialect::Rot1Prog, Op::Elevation));
        QVERIFY(!dialectSupports(Dialect::Rot1Prog, Op::StopElevation));
        // No velocity jog, no registers, no park, no version, no GS-232 extras.
        for (Dialect d : {Dialect::Rot2Prog, Dialect::Rot1Prog, Dialect::Md01}) {
            for (Op op : {Op::VelocityLeft, Op::VelocityUp, Op::ConfigRead, Op::ConfigWrite, Op::Park, Op::Reset,
                          Op::Version, Op::Status, Op::KeepAlive, Op::Offset, Op::Speed})
                QVERIFY2(!dialectSupports(d, op), describe(op));
            // The MD-01/02's move command; the others have none.
            for (Op op : {Op::MoveLeft, Op::MoveRight, Op::MoveUp, Op::MoveDown})
                QCOMPARE(dialectSupports(d, op), d == Dialect::Md01);
        }
    }

    // The line encoder writes no text for a binary dialect; the fixed
    // frames (status, stop) come from it, a set (which needs the
    // controller's resolution) does not.
    void lineEncoderRefuses()
    {
        for (Dialect d : {Dialect::Rot2Prog, Dialect::Rot1Prog, Dialect::Md01}) {
            QVERIFY(encodeSetPosition(10, 20, d).isEmpty());
            QCOMPARE(encodeQueryPosition(d), spid::encodeStatus());
            QCOMPARE(encodeStop(true, true, d), spid::encodeStop());
            QCOMPARE(encodeStop(true, false, d), spid::encodeStop()); // one frame stops both
            QVERIFY(encodeStop(false, false, d).isEmpty());
            QVERIFY(encodeToken(Message::number(Op::Azimuth, 10), d).isEmpty());
            QVERIFY(encodeLine({Message::query(Op::Azimuth)}, d).isEmpty());
            QVERIFY(encodeReport(Message::number(Op::Azimuth, 10), d).isEmpty());
            QCOMPARE(Parser::parseToken("AZ10", d).op, Op::Invalid);
        }
    }

    void encodesAsHamlib()
    {
        QCOMPARE(spid::encodeStatus(), bytes({0x57, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x1F, 0x20}));
        QCOMPARE(spid::encodeStop(), bytes({0x57, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x0F, 0x20}));
        // 2 × (360 + 10.5) = 741, 2 × (360 + 20) = 760
        QCOMPARE(spid::encodeSet(10.5, 20.0, Dialect::Rot2Prog, 2, 2).bytes,
                 QByteArray("\x57" "0741" "\x02" "0760" "\x02\x2F\x20", 13));
        // 1 × 360 = 360, 4 × (360 - 20) = 1360
        QCOMPARE(spid::encodeSet(0.0, -20.0, Dialect::Md01, 1, 4).bytes,
                 QByteArray("\x57" "0360" "\x01" "1360" "\x04\x2F\x20", 13));
        // Rot1Prog: whole degrees in H1..H3, '0' in H4, no resolution bytes.
        QCOMPARE(spid::encodeSet(123.0, 45.0, Dialect::Rot1Prog).bytes,
                 QByteArray("\x57" "4830" "\0\0\0\0\0\0" "\x2F\x20", 13));
        QCOMPARE(spid::encodeMove(spid::MoveBit::Left, Dialect::Md01).bytes,
                 bytes({0x57, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x14, 0x20}));
        QCOMPARE(spid::encodeReply(10.5, 20.0, Dialect::Rot2Prog, 2, 2), kReply);
        QCOMPARE(spid::encodeReply(123.0, 0.0, Dialect::Rot1Prog, 0, 0), bytes({0x57, 4, 8, 3, 0x20}));
    }

    void refusesBeforeEncoding_data()
    {
        QTest::addColumn<double>("az");
        QTest::addColumn<double>("el");
        QTest::addColumn<int>("pulses");
        QTest::addColumn<int>("dialect");
        QTest::newRow("az above 540") << 540.1 << 0.0 << 1 << int(Dialect::Rot2Prog);
        QTest::newRow("az below -180") << -180.5 << 0.0 << 1 << int(Dialect::Md01);
        QTest::newRow("el above 210") << 0.0 << 210.5 << 1 << int(Dialect::Rot2Prog);
        QTest::newRow("el below -20") << 0.0 << -21.0 << 1 << int(Dialect::Rot2Prog);
        QTest::newRow("az nan") << qQNaN() << 0.0 << 1 << int(Dialect::Rot1Prog);
        QTest::newRow("el infinite") << 0.0 << qInf() << 1 << int(Dialect::Md01);
        QTest::newRow("3 pulses") << 0.0 << 0.0 << 3 << int(Dialect::Rot2Prog);
        QTest::newRow("not spid") << 0.0 << 0.0 << 1 << int(Dialect::Gs232A);
    }

    void refusesBeforeEncoding()
    {
        QFETCH(double, az);
        QFETCH(double, el);
        QFETCH(int, pulses);
        QFETCH(int, dialect);
        const spid::Encoded e = spid::encodeSet(az, el, Dialect(dialect), pulses, pulses);
        QVERIFY(!e.ok());
        QVERIFY(e.bytes.isEmpty());
        QVERIFY(e.refusal && *e.refusal);
    }

    void edgesOfTheRanges()
    {
        QVERIFY(spid::encodeSet(-180, -20, Dialect::Rot2Prog, 4, 4).ok());
        QVERIFY(spid::encodeSet(540, 210, Dialect::Rot2Prog, 10, 10).ok());
        QCOMPARE(spid::encodeSet(540, 210, Dialect::Rot2Prog, 10, 10).bytes.mid(1, 4), QByteArray("9000"));
        QVERIFY(spid::encodeSet(10, 999, Dialect::Rot1Prog).ok()); // no elevation to check
        QVERIFY(!spid::encodeMove(spid::MoveBit::Left, Dialect::Rot2Prog).ok());
        QVERIFY(!spid::encodeMove(spid::MoveBit::Left | spid::MoveBit::Right, Dialect::Md01).ok());
        QVERIFY(!spid::encodeMove(0, Dialect::Md01).ok());
    }

    void readsReplies()
    {
        QCOMPARE(read(Dialect::Rot2Prog, kReply), QStringList{"reply 10.5 20 /2/2"});
        QCOMPARE(read(Dialect::Rot1Prog, bytes({0x57, 4, 8, 3, 0x20})), QStringList{"reply 123 0 /0/0"});
        // The resolution is detected from PH/PV.
        spid::Parser p(Dialect::Md01);
        QCOMPARE(p.azimuthPulses(), 0);
        p.feed(spid::encodeReply(-180.0, 210.0, Dialect::Md01, 4, 1), [](const Frame &) {});
        QCOMPARE(p.azimuthPulses(), 4);
        QCOMPARE(p.elevationPulses(), 1);
    }

    void readsCommands_data()
    {
        QTest::addColumn<int>("pulses");
        QTest::newRow("1") << 1;
        QTest::newRow("2") << 2;
        QTest::newRow("4") << 4;
        QTest::newRow("10") << 10;
    }

    void readsCommands()
    {
        QFETCH(int, pulses);
        const QByteArray set = spid::encodeSet(-12.5, 88.25, Dialect::Rot2Prog, pulses, pulses).bytes;
        const double az = std::round(pulses * (360 - 12.5)) / pulses - 360;
        const double el = std::round(pulses * (360 + 88.25)) / pulses - 360;
        QCOMPARE(read(Dialect::Rot2Prog, set + spid::encodeStatus() + spid::encodeStop()),
                 (QStringList{QStringLiteral("command 2f %1 %2 move0").arg(az).arg(el), "command 1f 0 0 move0",
                              "command 0f 0 0 move0"}));
    }

    void readsRot1ProgAndMoveCommands()
    {
        QCOMPARE(read(Dialect::Rot1Prog, spid::encodeSet(123, 0, Dialect::Rot1Prog).bytes),
                 QStringList{"command 2f 123 0 move0"});
        QCOMPARE(read(Dialect::Md01, spid::encodeMove(spid::MoveBit::Up, Dialect::Md01).bytes),
                 QStringList{"command 14 0 0 move4"});
        QCOMPARE(read(Dialect::Rot2Prog, spid::encodeMove(spid::MoveBit::Up, Dialect::Md01).bytes).size(), 1);
        QVERIFY(read(Dialect::Rot2Prog, spid::encodeMove(spid::MoveBit::Up, Dialect::Md01).bytes)[0].startsWith("refused"));
    }

    void refusesWhatCannotBeActedOn_data()
    {
        QTest::addColumn<int>("dialect");
        QTest::addColumn<QByteArray>("in");
        QTest::newRow("reply az 639.9") << int(Dialect::Rot2Prog) << bytes({0x57, 9, 9, 9, 9, 1, 3, 6, 0, 0, 1, 0x20});
        QTest::newRow("set el 220") << int(Dialect::Md01) << QByteArray("\x57" "0360" "\x01" "0580" "\x01\x2F\x20", 13);
        QTest::newRow("set without PH") << int(Dialect::Rot2Prog) << QByteArray("\x57" "0360" "\x00" "0360" "\x01\x2F\x20", 13);
        QTest::newRow("set zeros") << int(Dialect::Rot2Prog) << bytes({0x57, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0x2F, 0x20});
        QTest::newRow("rot1prog az 600") << int(Dialect::Rot1Prog) << QByteArray("\x57" "9600" "\0\0\0\0\0\0" "\x2F\x20", 13);
    }

    void refusesWhatCannotBeActedOn()
    {
        QFETCH(int, dialect);
        QFETCH(QByteArray, in);
        const QStringList out = read(Dialect(dialect), in);
        QCOMPARE(out.size(), 1);
        QVERIFY2(out[0].startsWith("refused: "), qPrintable(out[0]));
    }

    void resynchronises_data()
    {
        QTest::addColumn<int>("dialect");
        QTest::addColumn<QByteArray>("in");
        QTest::addColumn<QStringList>("expected");
        const QString r = "reply 10.5 20 /2/2";
        QTest::newRow("binary garbage") << int(Dialect::Rot2Prog) << bytes({0xFF, 0x00, 0x80}) + kReply
                                        << QStringList{"skipped 3", r};
        QTest::newRow("a stray start byte") << int(Dialect::Rot2Prog) << QByteArray("\x57") + kReply
                                            << QStringList{"skipped 1", r};
        QTest::newRow("a cut reply") << int(Dialect::Rot2Prog) << kReply.left(7) + kReply << QStringList{"skipped 7", r};
        QTest::newRow("a wrong end byte") << int(Dialect::Rot2Prog) << kReply.left(11) + 'X' + kReply
                                          << QStringList{"skipped 12", r};
        QTest::newRow("md01 log lines") << int(Dialect::Md01)
                                        << "Warning: W limit\r\n" + kReply + "MD-01 v2\r\n\r\n" + kReply
                                        << QStringList{"text 'Warning: W limit'", r, "text 'MD-01 v2'", r};
        QTest::newRow("a line cut by a frame") << int(Dialect::Md01) << "abc" + kReply << QStringList{"skipped 3", r};
        QTest::newRow("a line never ended") << int(Dialect::Md01) << kReply + "tail" << QStringList{r, "text 'tail'"};
        QTest::newRow("rot1prog after garbage") << int(Dialect::Rot1Prog) << QByteArray("\x57\x57\x01") + bytes({0x57, 4, 8, 3, 0x20})
                                                << QStringList{"skipped 3", "reply 123 0 /0/0"};
        QTest::newRow("a 12-byte reply in rot1prog") << int(Dialect::Rot1Prog) << kReply
                                                     << QStringList{"skipped 12"};
    }

    void resynchronises()
    {
        QFETCH(int, dialect);
        QFETCH(QByteArray, in);
        QFETCH(QStringList, expected);
        QCOMPARE(read(Dialect(dialect), in), expected);
    }

    // The same frames whether the bytes come at once, one by one or in
    // random pieces, as they do from a serial port.
    void splitAcrossReads()
    {
        const QByteArray in = QByteArray("\xFF\x57\x01") + kReply + "Warning: W\r\n" + kReply.left(5) + kReply
                              + spid::encodeStatus() + "x" + kReply;
        const QStringList whole = read(Dialect::Md01, in);
        QCOMPARE(whole.size(), 8);
        QStringList bytewise;
        spid::Parser one(Dialect::Md01);
        for (char c : in)
            one.feed(QByteArrayView(&c, 1), [&](const Frame &f) { bytewise << dump(f); });
        one.flush([&](const Frame &f) { bytewise << dump(f); });
        QCOMPARE(bytewise, whole);
        QRandomGenerator random(14);
        for (int round = 0; round < 50; ++round) {
            QStringList chunked;
            spid::Parser p(Dialect::Md01);
            for (qsizetype at = 0; at < in.size();) {
                const qsizetype n = std::min<qsizetype>(random.bounded(1, 9), in.size() - at);
                p.feed(QByteArrayView(in).sliced(at, n), [&](const Frame &f) { chunked << dump(f); });
                at += n;
            }
            p.flush([&](const Frame &f) { chunked << dump(f); });
            QCOMPARE(chunked, whole);
        }
    }

    // Memory is bounded: a long text line is cut once, endless garbage only counted.
    void capsWhatItHolds()
    {
        const QByteArray longLine = QByteArray(1000, 'a') + "\r\n";
        const QStringList out = read(Dialect::Md01, longLine + kReply);
        QCOMPARE(out.size(), 2);
        QCOMPARE(out[0], "text '" + QString(spid::Parser::kTextCap, 'a') + "' cut");
        QCOMPARE(out[1], "reply 10.5 20 /2/2");
        QByteArray garbage(100000, '\0');
        for (qsizetype i = 0; i < garbage.size(); ++i)
            garbage[i] = char(0x80 | (i & 0x7F));
        QCOMPARE(read(Dialect::Rot2Prog, garbage + kReply), (QStringList{"skipped 100000", "reply 10.5 20 /2/2"}));
        QVERIFY(sizeof(spid::Parser) < 8 * 1024);
    }

    void heldBytesAreReportedOnFlush()
    {
        spid::Parser p(Dialect::Rot2Prog);
        QStringList out;
        p.feed(kReply.left(6), [&](const Frame &f) { out << dump(f); });
        QVERIFY(out.isEmpty());
        QVERIFY(p.hasUnfinishedFrame());
        p.flush([&](const Frame &f) { out << dump(f); });
        QCOMPARE(out, QStringList{"skipped 6"});
        QVERIFY(!p.hasUnfinishedFrame());
    }

    // The message parser hands SPID frames out as messages.
    void messageParserReadsFrames()
    {
        auto messages = [](Dialect d, QByteArrayView in) {
            QStringList out;
            Parser p(d);
            p.feed(in, [&](const Message &m) { out << dumpMessage(m); });
            p.flush([&](const Message &m) { out << dumpMessage(m); });
            return out;
        };
        QCOMPARE(messages(Dialect::Rot2Prog, kReply), (QStringList{"azimuth=10.5", "elevation=20|"}));
        QCOMPARE(messages(Dialect::Rot1Prog, bytes({0x57, 4, 8, 3, 0x20})), (QStringList{"azimuth=123", "elevation=0|"}));
        QCOMPARE(messages(Dialect::Rot1Prog, spid::encodeStop()), QStringList{"stop azimuth|"});
        QCOMPARE(messages(Dialect::Md01, spid::encodeStatus() + spid::encodeStop()),
                 (QStringList{"azimuth", "elevation|", "stop azimuth", "stop elevation|"}));
        QCOMPARE(messages(Dialect::Md01, "log\r\n" + spid::encodeMove(spid::MoveBit::Right | spid::MoveBit::Down, Dialect::Md01).bytes),
                 (QStringList{"alarm 'log'|", "move right", "move down|"}));
        const QStringList bad = messages(Dialect::Rot2Prog, "\x01\x02");
        QCOMPARE(bad.size(), 1);
        QVERIFY(bad[0].startsWith("unreadable input"));
    }
};

QTEST_APPLESS_MAIN(SpidCodecTest)
#include "tst_spidcodec.moc"
