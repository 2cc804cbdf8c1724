// SPDX-License-Identifier: GPL-3.0-or-later
// The encoder per dialect: the exact bytes Hamlib's backends and the Easycomm III derivative
// controller send, and a round trip through the parser for every command.
// The codec the session speaks through (codec.h): the same bytes, chosen by
// what the dialect can do rather than by its name.

#include "messagedump.h"
#include "protocol/codec.h"
#include "protocol/encoder.h"
#include "protocol/parser.h"
#include "protocol/spidcodec.h"

#include <QFile>
#include <QMap>
#include <QTest>

#include <limits>

using namespace slew::protocol;

Q_DECLARE_METATYPE(slew::protocol::Dialect)
Q_DECLARE_METATYPE(slew::protocol::Message)

class EncoderTest : public QObject {
    Q_OBJECT
private slots:
    void hamlibWireStrings();
    void gs232WireStrings();
    void rotctldWireStrings();
    void rotctldCannotDoWhatItLacks();
    void rotctldCommandsReadBack();
    void tokens_data();
    void tokens();
    void unsupportedCommandsEncodeToNothing();
    void roundTrip_data();
    void roundTrip();
    void numbersNeverUseExponentOrLocale();
    void hugeNumbersAreWrittenWhole();
    void wholeNumbersAreDefinedForEveryDouble();
    void dialectNames();
    void theDialectTableIsDocumented();
    void codecsSetByWhatTheDialectCan();
    void codecsJogByWhatTheDialectHas();
    void aSpidCodecLearnsItsResolutionFromReplies();
    void codecsRefuseRawLinesTheyCannotVouchFor();
};

void EncoderTest::hamlibWireStrings()
{
    // Peers (docs/protocol.md): `P 10.5 20.25` makes model 202/204 send `AZ10.5 EL20.2`.
    QCOMPARE(encodeSetPosition(10.5, 20.25, Dialect::Easycomm2), QByteArray("AZ10.5 EL20.2\n"));
    QCOMPARE(encodeSetPosition(10.5, 20.25, Dialect::SatNogs), QByteArray("AZ10.5 EL20.2\n"));
    // Model 201 (Easycomm I) sends the whole line.
    QCOMPARE(encodeSetPosition(10.5, 20.25, Dialect::Easycomm1),
             QByteArray("AZ10.5 EL20.2 UP000 XXX DN000 XXX\n"));
    // The Easycomm III derivative takes two decimals.
    QCOMPARE(encodeSetPosition(10.5, 20.25, Dialect::Easycomm3), QByteArray("AZ10.50 EL20.25\n"));
    QCOMPARE(encodeQueryPosition(Dialect::Easycomm2), QByteArray("AZ EL\n"));
    QCOMPARE(encodeQueryPosition(Dialect::Easycomm1), QByteArray());
    QCOMPARE(encodeStop(true, true, Dialect::SatNogs), QByteArray("SA SE\n"));
    QCOMPARE(encodeStop(false, true, Dialect::Easycomm3), QByteArray("SE\n"));
    // The zero speed that brakes and holds what a stop released.
    QCOMPARE(encodeStopHold(true, true, Dialect::Easycomm3), QByteArray("VL000 VU000\n"));
    QCOMPARE(encodeStopHold(true, true, Dialect::SatNogs), QByteArray("VL0000 VU0000\n"));
    QCOMPARE(encodeStopHold(true, false, Dialect::Easycomm3), QByteArray("VL000\n"));
    QCOMPARE(encodeStopHold(false, true, Dialect::Easycomm3), QByteArray("VU000\n"));
    QVERIFY(encodeStopHold(true, true, Dialect::Easycomm2).isEmpty()); // no speed commands
    QVERIFY(encodeStopHold(true, true, Dialect::Gs232B).isEmpty());
    // `M 16 50` on model 204 sends VR4900 (speed (50-1)*100 mdeg/s).
    QCOMPARE(encodeLine({Message::number(Op::VelocityRight, 4900)}, Dialect::SatNogs), QByteArray("VR4900\n"));
    QCOMPARE(encodeLine({Message::number(Op::VelocityLeft, 50)}, Dialect::SatNogs), QByteArray("VL0050\n"));
    QCOMPARE(encodeLine({Message::number(Op::VelocityLeft, 50)}, Dialect::Easycomm3), QByteArray("VL050\n"));
    QCOMPARE(encodeLine({Message::query(Op::Park)}, Dialect::Easycomm2), QByteArray("PARK\n"));
    QCOMPARE(encodeLine({Message::query(Op::Reset)}, Dialect::Easycomm2), QByteArray("RESET\n"));
    QCOMPARE(encodeLine({Message::query(Op::MoveUp)}, Dialect::Easycomm2), QByteArray("MU\n"));
    // SatNOGS reads the register after a space.
    QCOMPARE(encodeLine({Message::query(Op::ConfigRead, 1)}, Dialect::SatNogs), QByteArray("CR 1\n"));
    QCOMPARE(encodeLine({Message::query(Op::ConfigRead, 1)}, Dialect::Easycomm3), QByteArray("CR1\n"));
}

void EncoderTest::gs232WireStrings()
{
    // What Hamlib's gs232a (601) and gs232b (603) backends send.
    for (Dialect d : {Dialect::Gs232A, Dialect::Gs232B}) {
        QCOMPARE(encodeSetPosition(10, 20, d), QByteArray("W010 020\r"));
        QCOMPARE(encodeSetPosition(359.6, 89.4, d), QByteArray("W360 089\r"));
        QCOMPARE(encodeQueryPosition(d), QByteArray("C2\r"));
        QCOMPARE(encodeStop(true, true, d), QByteArray("S\r"));
        QCOMPARE(encodeStop(true, false, d), QByteArray("A\r"));
        QCOMPARE(encodeStop(false, true, d), QByteArray("E\r"));
        QCOMPARE(encodeLine({Message::number(Op::Speed, 2), Message::query(Op::MoveRight)}, d), QByteArray("X2\rR\r"));
        QCOMPARE(encodeLine({Message::query(Op::MoveLeft)}, d), QByteArray("L\r"));
        QCOMPARE(encodeLine({Message::query(Op::MoveUp)}, d), QByteArray("U\r"));
        QCOMPARE(encodeLine({Message::query(Op::MoveDown)}, d), QByteArray("D\r"));
        QCOMPARE(encodeLine({Message::number(Op::Azimuth, 45)}, d), QByteArray("M045\r"));
        QCOMPARE(encodeLine({Message::query(Op::Elevation)}, d), QByteArray("B\r"));
        // The easycom library's relative move: each offset signed, three digits.
        QCOMPARE(encodeOffset(10, -5, d), QByteArray("O+010-005\r"));
        QCOMPARE(encodeOffset(-120.4, 0, d), QByteArray("O-120+000\r"));
        // The easycom library's status query, and the answer Slew chose.
        QCOMPARE(encodeLine({Message::query(Op::Status)}, d), QByteArray("GS\r"));
        QCOMPARE(encodeReport(Message::number(Op::Status, 6), d), QByteArray("ST=6"));
        QVERIFY(!dialectSupports(d, Op::ErrorFlags)); // no GE on a GS-232
        // No park, reset, config or velocity commands on a GS-232.
        QVERIFY(encodeLine({Message::query(Op::Park)}, d).isEmpty());
        QVERIFY(encodeLine({Message::number(Op::VelocityRight, 100)}, d).isEmpty());
        QVERIFY(encodeLine({Message::query(Op::ConfigRead, 1)}, d).isEmpty());
    }
    // Only GS-232 has a relative move on the wire.
    for (Dialect d : {Dialect::Easycomm1, Dialect::Easycomm2, Dialect::Easycomm3, Dialect::SatNogs, Dialect::Rotctld}) {
        QVERIFY(!dialectSupports(d, Op::Offset));
        QVERIFY(encodeOffset(10, -5, d).isEmpty());
    }
    // Reports, as the simulator answers.
    QCOMPARE(encodeReport(Message::number(Op::Azimuth, 10), Dialect::Gs232A) + reportSeparator(Dialect::Gs232A)
                 + encodeReport(Message::number(Op::Elevation, 20), Dialect::Gs232A),
             QByteArray("+0010+0020"));
    QCOMPARE(encodeReport(Message::number(Op::Azimuth, 10), Dialect::Gs232B) + reportSeparator(Dialect::Gs232B)
                 + encodeReport(Message::number(Op::Elevation, 20), Dialect::Gs232B),
             QByteArray("AZ=010  EL=020"));
    QCOMPARE(encodeReport(Message::number(Op::Azimuth, 10.5), Dialect::Easycomm2), QByteArray("AZ10.5"));
}

void EncoderTest::rotctldWireStrings()
{
    // Hamlib's rotctld(1) manual page: one command a line, ended with `\n`.
    const auto r = Dialect::Rotctld;
    QCOMPARE(encodeSetPosition(10.5, 20.25, r), QByteArray("P 10.50 20.25\n"));
    QCOMPARE(encodeSetPosition(-0.001, 90, r), QByteArray("P 0.00 90.00\n"));
    QCOMPARE(encodeQueryPosition(r), QByteArray("p\n"));
    // S stops both axes, whichever was asked: more than asked, never less.
    QCOMPARE(encodeStop(true, true, r), QByteArray("S\n"));
    QCOMPARE(encodeStop(true, false, r), QByteArray("S\n"));
    QCOMPARE(encodeStop(false, true, r), QByteArray("S\n"));
    QVERIFY(encodeStop(false, false, r).isEmpty());
    QVERIFY(encodeStopHold(true, true, r).isEmpty()); // no speed commands to hold with
    QCOMPARE(encodeLine({Message::query(Op::Park)}, r), QByteArray("K\n"));
    QCOMPARE(encodeLine({Message::query(Op::Reset)}, r), QByteArray("R 1\n"));
    QCOMPARE(encodeLine({Message::query(Op::Version)}, r), QByteArray("_\n"));
    // Directions as Hamlib numbers them: UP 2, DOWN 4, LEFT 8, RIGHT 16.
    QCOMPARE(encodeLine({Message::query(Op::MoveUp)}, r), QByteArray("M 2 50\n"));
    QCOMPARE(encodeLine({Message::query(Op::MoveDown)}, r), QByteArray("M 4 50\n"));
    QCOMPARE(encodeLine({Message::query(Op::MoveLeft)}, r), QByteArray("M 8 50\n"));
    QCOMPARE(encodeLine({Message::query(Op::MoveRight)}, r), QByteArray("M 16 50\n"));
    // The answer lines of `p`, as a peer writes them.
    QCOMPARE(encodeReport(Message::number(Op::Azimuth, 180), r) + reportSeparator(r)
                 + encodeReport(Message::number(Op::Elevation, 45), r),
             QByteArray("180.00\n45.00"));
    QCOMPARE(lineTerminator(r), '\n');
    QVERIFY(setsBothAxesTogether(r));
    QVERIFY(!setsBothAxesTogether(Dialect::Easycomm2));
}

void EncoderTest::rotctldCannotDoWhatItLacks()
{
    const auto r = Dialect::Rotctld;
    // What rotctld has no command for is unsupported in the table, so the
    // session refuses it and the window greys it, rather than sending it.
    for (Op op : {Op::ConfigRead, Op::ConfigWrite, Op::Status, Op::ErrorFlags, Op::ReadInput, Op::ReadAnalog,
                  Op::Encoders, Op::VelocityLeft, Op::VelocityRight, Op::VelocityUp, Op::VelocityDown,
                  Op::UplinkFreq, Op::SetOutput, Op::Time, Op::Speed, Op::KeepAlive}) {
        QVERIFY2(!dialectSupports(r, op), describe(op));
        QVERIFY(encodeToken(Message::query(op, 1), r).isEmpty());
    }
    for (Op op : {Op::Azimuth, Op::Elevation, Op::MoveLeft, Op::MoveRight, Op::MoveUp, Op::MoveDown,
                  Op::StopAzimuth, Op::StopElevation, Op::Park, Op::Reset, Op::Version})
        QVERIFY2(dialectSupports(r, op), describe(op));
    // P always takes both axes: a lone angle has no form.
    QVERIFY(encodeToken(Message::number(Op::Azimuth, 10), r).isEmpty());
    QVERIFY(encodeLine({Message::number(Op::Elevation, 10)}, r).isEmpty());
    QVERIFY(encodeToken(Message::word(Op::Version, "x"), r).isEmpty());
}

void EncoderTest::rotctldCommandsReadBack()
{
    // What the encoder writes, the parser reads as the same messages: the
    // session's raw line and the tests' scripted peer both rely on it.
    const auto r = Dialect::Rotctld;
    struct Case {
        QByteArray wire;
        QStringList messages;
    };
    const Case cases[] = {
        {encodeSetPosition(10.5, 20.25, r), {"azimuth=10.5", "elevation=20.25|"}},
        {encodeQueryPosition(r), {"azimuth", "elevation|"}},
        {encodeStop(true, true, r), {"stop azimuth", "stop elevation|"}},
        {encodeLine({Message::query(Op::Park)}, r), {"park|"}},
        {encodeLine({Message::query(Op::Reset)}, r), {"reset and home|"}},
        {encodeLine({Message::query(Op::Version)}, r), {"version|"}},
        {encodeLine({Message::query(Op::MoveRight)}, r), {"move right|"}},
        {encodeLine({Message::query(Op::MoveDown)}, r), {"move down|"}},
    };
    for (const Case &c : cases) {
        Parser parser(r);
        QCOMPARE(parseAll(parser, c.wire), c.messages);
    }
}

void EncoderTest::tokens_data()
{
    QTest::addColumn<Dialect>("dialect");
    QTest::addColumn<Message>("message");
    QTest::addColumn<QByteArray>("wire");
    const auto e2 = Dialect::Easycomm2;
    const auto e3 = Dialect::Easycomm3;
    QTest::newRow("AZ get") << e2 << Message::query(Op::Azimuth) << QByteArray("AZ");
    QTest::newRow("EL set") << e2 << Message::number(Op::Elevation, 45) << QByteArray("EL45.0");
    QTest::newRow("UP") << e2 << Message::number(Op::UplinkFreq, 1231231231) << QByteArray("UP1231231231");
    QTest::newRow("DN") << e2 << Message::number(Op::DownlinkFreq, 435000000) << QByteArray("DN435000000");
    QTest::newRow("DM") << e2 << Message::word(Op::DownlinkMode, "LSB") << QByteArray("DMLSB");
    QTest::newRow("UM") << e2 << Message::word(Op::UplinkMode, "CW") << QByteArray("UMCW");
    QTest::newRow("DR") << e2 << Message::number(Op::DownlinkRadio, 999) << QByteArray("DR999");
    QTest::newRow("UR") << e2 << Message::number(Op::UplinkRadio, 1) << QByteArray("UR1");
    QTest::newRow("ML") << e2 << Message::query(Op::MoveLeft) << QByteArray("ML");
    QTest::newRow("MR") << e2 << Message::query(Op::MoveRight) << QByteArray("MR");
    QTest::newRow("MD") << e2 << Message::query(Op::MoveDown) << QByteArray("MD");
    QTest::newRow("AO") << e2 << Message::query(Op::Aos) << QByteArray("AO");
    QTest::newRow("LO") << e2 << Message::query(Op::Los) << QByteArray("LO");
    QTest::newRow("OP") << e2 << Message::number(Op::SetOutput, 1, 0) << QByteArray("OP0,1");
    QTest::newRow("IP") << e2 << Message::query(Op::ReadInput, 3) << QByteArray("IP3");
    QTest::newRow("AN") << e2 << Message::query(Op::ReadAnalog, 999) << QByteArray("AN999");
    QTest::newRow("ST") << e2 << Message::word(Op::Time, "22:01:19:02:30:16") << QByteArray("ST22:01:19:02:30:16");
    QTest::newRow("VE") << e2 << Message::query(Op::Version) << QByteArray("VE");
    QTest::newRow("VU") << e3 << Message::number(Op::VelocityUp, 1500) << QByteArray("VU1500");
    QTest::newRow("VD") << e3 << Message::number(Op::VelocityDown, 7) << QByteArray("VD007");
    QTest::newRow("CW text") << e3 << Message::word(Op::ConfigWrite, "0.85", 1) << QByteArray("CW1,0.85");
    QTest::newRow("CW number") << e3 << Message::number(Op::ConfigWrite, 180, 7) << QByteArray("CW7,180.000");
    QTest::newRow("GS") << e3 << Message::query(Op::Status) << QByteArray("GS");
    QTest::newRow("GE") << e3 << Message::query(Op::ErrorFlags) << QByteArray("GE");
    QTest::newRow("ENC") << e3 << Message::query(Op::Encoders) << QByteArray("\\?ENC");
    QTest::newRow("negative zero") << e3 << Message::number(Op::Azimuth, -0.001) << QByteArray("AZ0.00");
}

void EncoderTest::tokens()
{
    QFETCH(Dialect, dialect);
    QFETCH(Message, message);
    QFETCH(QByteArray, wire);
    QCOMPARE(encodeToken(message, dialect), wire);
}

void EncoderTest::unsupportedCommandsEncodeToNothing()
{
    QVERIFY(encodeToken(Message::query(Op::Status), Dialect::Easycomm2).isEmpty());
    QVERIFY(encodeToken(Message::query(Op::Encoders), Dialect::SatNogs).isEmpty());
    QVERIFY(encodeToken(Message::query(Op::MoveLeft), Dialect::Easycomm1).isEmpty());
    // One unsupported token spoils the whole line rather than sending half of it.
    QVERIFY(encodeLine({Message::query(Op::Azimuth), Message::query(Op::Status)}, Dialect::Easycomm2).isEmpty());
    QVERIFY(encodeStop(true, true, Dialect::Easycomm1).isEmpty());
}

void EncoderTest::roundTrip_data()
{
    QTest::addColumn<Dialect>("dialect");
    QTest::addColumn<Message>("message");
    const Message all[] = {
        Message::number(Op::Azimuth, 359.9),       Message::number(Op::Elevation, 0.1),
        Message::query(Op::Azimuth),               Message::number(Op::UplinkFreq, 145800000),
        Message::word(Op::UplinkMode, "FM"),       Message::query(Op::MoveRight),
        Message::query(Op::StopAzimuth),           Message::query(Op::StopElevation),
        Message::query(Op::ReadInput, 7),          Message::query(Op::ReadAnalog, 2),
        Message::query(Op::Version),               Message::word(Op::Time, "26:11:21:23:00:00"),
        Message::number(Op::VelocityRight, 4900),  Message::query(Op::ConfigRead, 12),
        Message::word(Op::ConfigWrite, "2.5", 4),  Message::query(Op::Status),
        Message::query(Op::ErrorFlags),            Message::query(Op::Reset),
        Message::query(Op::Park),                  Message::query(Op::Encoders),
    };
    for (Dialect d : {Dialect::Easycomm2, Dialect::Easycomm3, Dialect::SatNogs, Dialect::Gs232A, Dialect::Gs232B}) {
        for (const Message &m : all) {
            if (dialectSupports(d, m.op) && !encodeToken(m, d).isEmpty()) {
                const QString name = dialectName(d) + ' ' + QString::fromLatin1(encodeToken(m, d));
                QTest::newRow(qPrintable(name)) << d << m;
            }
        }
    }
}

void EncoderTest::roundTrip()
{
    QFETCH(Dialect, dialect);
    QFETCH(Message, message);
    Parser parser(dialect);
    QList<Message> out;
    parser.feed(encodeLine({message}, dialect), [&](const Message &m) { out << m; });
    QCOMPARE(out.size(), 1);
    Message expected = message;
    if (isGs232(dialect) && expected.hasValue)
        expected.value = std::round(expected.value); // GS-232 carries whole degrees
    // Text arguments come back with their numeric reading too.
    if (out[0].hasValue && !expected.hasValue && !expected.text.isEmpty()) {
        expected.hasValue = true;
        expected.value = out[0].value;
    }
    QVERIFY2(out[0] == expected, qPrintable(dumpMessage(out[0]) + " != " + dumpMessage(expected)));
}

void EncoderTest::numbersNeverUseExponentOrLocale()
{
    QLocale::setDefault(QLocale(QLocale::German));
    QCOMPARE(formatNumber(1e-9, 2), QByteArray("0.00"));
    QCOMPARE(formatNumber(1234567.891, 1), QByteArray("1234567.9"));
    QCOMPARE(formatNumber(-12.5, 1), QByteArray("-12.5"));
    QCOMPARE(formatNumber(qQNaN(), 1), QByteArray("0.0"));
    QLocale::setDefault(QLocale::c());
}

// snprintf once reported the length the number needed, more than the buffer
// held, and the bytes past the buffer were copied out (found by fuzz_rotctldrequest
// in the same code of rotctldrequest.cpp).
void EncoderTest::hugeNumbersAreWrittenWhole()
{
    const QByteArray big = formatNumber(1e300, 2);
    QCOMPARE(big.size(), 301 + 3);
    QVERIFY(big.startsWith("10000000000000000525"));
    QVERIFY(big.endsWith(".00"));
    const QByteArray largest = formatNumber(-1.7976931348623157e308, 1);
    QCOMPARE(largest.size(), 1 + 309 + 2);
    QVERIFY(largest.startsWith("-17976931348623157"));
}

// llround of a NaN or of more than a long long holds is undefined, and so is
// llabs of the LLONG_MIN it may return (UBSan's finding in velocity()). The
// session never sends such values; the encoder stays defined all the same.
void EncoderTest::wholeNumbersAreDefinedForEveryDouble()
{
    const double inf = std::numeric_limits<double>::infinity();
    QCOMPARE(encodeLine({Message::number(Op::VelocityLeft, 1e300)}, Dialect::Easycomm3),
             QByteArray("VL1000000000000000\n"));
    QCOMPARE(encodeLine({Message::number(Op::VelocityRight, -inf)}, Dialect::Easycomm3),
             QByteArray("VR1000000000000000\n"));
    QCOMPARE(encodeLine({Message::number(Op::VelocityUp, qQNaN())}, Dialect::SatNogs), QByteArray("VU0000\n"));
    QCOMPARE(encodeLine({Message::number(Op::VelocityDown, -9.3e18)}, Dialect::SatNogs),
             QByteArray("VD1000000000000000\n"));
    const QByteArray gs = encodeSetPosition(inf, qQNaN(), Dialect::Gs232B);
    QCOMPARE(gs, QByteArray("W1000000000000000 000\r"));
}

void EncoderTest::dialectNames()
{
    for (Dialect d : allDialects())
        QCOMPARE(dialectFromName(dialectName(d)), std::optional<Dialect>(d));
    QCOMPARE(allDialects().size(), 11); // with the three SPID dialects
    QCOMPARE(dialectFromName(u"rotctld"), std::optional<Dialect>(Dialect::Rotctld));
    QCOMPARE(dialectFromName(u"SATNOGS"), std::optional<Dialect>(Dialect::SatNogs));
    QVERIFY(!dialectFromName(u"gs232").has_value());
    QCOMPARE(dialectFromName(u"GS232B"), std::optional<Dialect>(Dialect::Gs232B));
}

// docs/protocol.md shows the dialect table; its copy and the code's agree,
// row by row and column by column, and the Hamlib models are Hamlib's own
// numbers for the same protocols (rotlist: 201, 202, 204, 601, 603, 901-903).
void EncoderTest::theDialectTableIsDocumented()
{
    QFile doc(QStringLiteral(SLEW_SOURCE_DIR "/docs/protocol.md"));
    QVERIFY(doc.open(QIODevice::ReadOnly | QIODevice::Text));
    const QString text = QString::fromUtf8(doc.readAll());
    const qsizetype start = text.indexOf(QStringLiteral("### The dialect table"));
    QVERIFY(start >= 0);
    const QStringList lines = text.mid(start).split(u'\n');
    const auto lineEnd = [](char c) {
        return c == '\n' ? QStringLiteral("LF") : c == '\r' ? QStringLiteral("CR") : QStringLiteral("—");
    };
    const auto yesNo = [](bool b) { return b ? QStringLiteral("yes") : QStringLiteral("no"); };
    const QMap<DialectFamily, QString> families{{DialectFamily::Easycomm, "Easycomm"}, {DialectFamily::Gs232, "GS-232"},
                                                {DialectFamily::Rotctld, "rotctld"}, {DialectFamily::Micro2g, "Micro-2g"},
                                                {DialectFamily::Spid, "SPID"}};
    int rows = 0;
    for (const DialectRow &row : kDialects) {
        const QString expected = QStringLiteral("| `%1` | %2 | %3 | %4 | %5 | %6 | %7 | %8 | %9 |")
                                     .arg(QString::fromLatin1(row.name), families.value(row.family),
                                          row.framing == Framing::Lines ? QStringLiteral("lines") : QStringLiteral("SPID frames"))
                                     .arg(row.hamlibModel)
                                     .arg(lineEnd(row.terminator))
                                     .arg(row.angleDecimals)
                                     .arg(yesNo(row.azimuthOnly))
                                     .arg(row.rotorsOnLine)
                                     .arg(yesNo(row.setsBothAxes));
        QVERIFY2(lines.contains(expected), qPrintable(QStringLiteral("docs/protocol.md lacks: ") + expected));
        ++rows;
    }
    QCOMPARE(rows, 11);
    // What each can do, as the codec tells the session: the second table.
    const auto jogWay = [](const Codec &c) {
        if (!c.answers())
            return QStringLiteral("none (no position to start from)");
        if (!c.jogsItself())
            return QStringLiteral("legs of set-position");
        if (c.supports(Op::VelocityLeft))
            return QStringLiteral("speed");
        return c.readsTextLines() ? QStringLiteral("move") : QStringLiteral("move frame");
    };
    QStringList missing;
    for (const DialectRow &row : kDialects) {
        const auto c = Codec::forDialect(row.dialect);
        const QString expected = QStringLiteral("| `%1` | %2 | %3 | %4 | %5 | %6 | %7 | %8 | %9 |")
                                     .arg(QString::fromLatin1(row.name), yesNo(c->answers()), jogWay(*c),
                                          yesNo(!c->stop(true, true).isEmpty()), yesNo(c->supports(Op::Park)),
                                          yesNo(c->supports(Op::Reset)), yesNo(c->supports(Op::ConfigRead)),
                                          yesNo(c->supports(Op::UplinkFreq)), yesNo(c->supports(Op::KeepAlive)));
        if (!lines.contains(expected))
            missing << expected;
    }
    QVERIFY2(missing.isEmpty(), qPrintable(QStringLiteral("docs/protocol.md lacks:\n") + missing.join(u'\n')));
    const QMap<Dialect, int> hamlib{{Dialect::Easycomm1, 201}, {Dialect::Easycomm2, 202}, {Dialect::SatNogs, 204},
                                    {Dialect::Gs232A, 601},    {Dialect::Gs232B, 603},    {Dialect::Rot2Prog, 901},
                                    {Dialect::Rot1Prog, 902},  {Dialect::Md01, 903}};
    for (auto it = hamlib.cbegin(); it != hamlib.cend(); ++it)
        QCOMPARE(dialectRow(it.key()).hamlibModel, it.value());
}

// The session's set, one axis or both, and the finest step it makes.
void EncoderTest::codecsSetByWhatTheDialectCan()
{
    const auto easycomm = Codec::forDialect(Dialect::Easycomm3);
    QCOMPARE(easycomm->setPosition(123.4, 45.6).bytes, encodeSetPosition(123.4, 45.6, Dialect::Easycomm3));
    QCOMPARE(easycomm->setAxis(true, 123.4).bytes, encodeLine({Message::number(Op::Azimuth, 123.4)}, Dialect::Easycomm3));
    QCOMPARE(easycomm->setResolutionDeg(), 0.01);
    QVERIFY(easycomm->answers() && easycomm->readsTextLines() && !easycomm->stopHaltsEveryAxis());
    // GS-232 sets both axes in one W: no single axis.
    const auto gs232 = Codec::forDialect(Dialect::Gs232B);
    QVERIFY(gs232->setsBothAxes());
    QVERIFY(!gs232->setAxis(false, 30).ok());
    QCOMPARE(gs232->setResolutionDeg(), 1.0);
    QCOMPARE(gs232->stop(true, true), encodeStop(true, true, Dialect::Gs232B));
    // Easycomm I answers nothing; Micro-2g writes the rotor it was given.
    QVERIFY(!Codec::forDialect(Dialect::Easycomm1)->answers());
    const auto micro2g = Codec::forDialect(Dialect::Micro2g, 3);
    QCOMPARE(micro2g->queryPosition(), encodeQueryPosition(Dialect::Micro2g, 3));
    QVERIFY(micro2g->azimuthIsBearing() && micro2g->isAzimuthOnly());
    QCOMPARE(micro2g->row().rotorsOnLine, 4);
    // SPID: frames, a stop that halts both axes, no lines.
    const auto spid = Codec::forDialect(Dialect::Rot2Prog);
    QVERIFY(!spid->readsTextLines() && spid->stopHaltsEveryAxis());
    QCOMPARE(spid->queryPosition(), spid::encodeStatus());
    QCOMPARE(spid->stop(false, true), spid::encodeStop());
    QVERIFY(spid->line({Message::query(Op::Park)}).isEmpty());
}

// A jog is a speed where the dialect has speeds, a bare move where it has
// moves, the MD-01's one frame for both axes, and otherwise legs of
// set-position (session/joglegs.h), which the codec does not write.
void EncoderTest::codecsJogByWhatTheDialectHas()
{
    const auto easycomm = Codec::forDialect(Dialect::Easycomm3);
    QVERIFY(easycomm->jogsItself());
    const Encoded speed = easycomm->jog({-1.5, 0.0}, true);
    QCOMPARE(speed.bytes, encodeLine({Message::number(Op::VelocityLeft, 1500)}, Dialect::Easycomm3));
    QVERIFY(speed.echo && speed.echo->op == Op::VelocityLeft); // an echo is not a report
    const Encoded down = Codec::forDialect(Dialect::Gs232A)->jog({0.0, -2.0}, false);
    QCOMPARE(down.bytes, encodeLine({Message::query(Op::MoveDown)}, Dialect::Gs232A));
    QVERIFY(!down.echo);
    const Encoded both = Codec::forDialect(Dialect::Md01)->jog({1.0, -1.0}, false);
    QCOMPARE(both.bytes, spid::encodeMove(spid::MoveBit::Right | spid::MoveBit::Down, Dialect::Md01).bytes);
    QCOMPARE(Codec::forDialect(Dialect::Rotctld)->jog({0.0, 2.0}, false).bytes,
             encodeLine({Message::query(Op::MoveUp)}, Dialect::Rotctld));
    for (Dialect d : {Dialect::Rot2Prog, Dialect::Rot1Prog, Dialect::Micro2g, Dialect::Easycomm1})
        QVERIFY2(!Codec::forDialect(d)->jogsItself(), qPrintable(dialectName(d)));
    const Encoded none = Codec::forDialect(Dialect::Micro2g)->jog({1.0, 0.0}, true);
    QVERIFY(none.bytes.isEmpty());
    QCOMPARE(none.refusal, QStringLiteral("micro2g has no command to move an axis"));
}

// A SPID set counts in the controller's pulses a degree, which only its
// replies tell: until one has come, a set is refused, not guessed.
void EncoderTest::aSpidCodecLearnsItsResolutionFromReplies()
{
    const auto spid = Codec::forDialect(Dialect::Rot2Prog);
    const Encoded early = spid->setPosition(100.0, 20.0);
    QVERIFY(early.bytes.isEmpty());
    QVERIFY2(early.refusal.contains(QStringLiteral("resolution is not known yet")), qPrintable(early.refusal));
    int positions = 0;
    spid->feed(spid::encodeReply(10.5, 20.0, Dialect::Rot2Prog, 2, 2), [&](const Message &m) {
        positions += m.op == Op::Azimuth || m.op == Op::Elevation;
    });
    QCOMPARE(positions, 2);
    QCOMPARE(spid->setResolutionDeg(), 0.5);
    QCOMPARE(spid->setPosition(100.0, 20.0).bytes, spid::encodeSet(100.0, 20.0, Dialect::Rot2Prog, 2, 2).bytes);
    // Outside what a frame holds: refused with the frame's reason.
    QVERIFY(!spid->setPosition(600.0, 20.0).ok());
    // Rot1Prog's whole degrees need no reply first.
    const auto rot1 = Codec::forDialect(Dialect::Rot1Prog);
    QCOMPARE(rot1->setPosition(123.0, 0.0).bytes, spid::encodeSet(123.0, 0.0, Dialect::Rot1Prog).bytes);
    QCOMPARE(rot1->setResolutionDeg(), 1.0);
}

// An operator's raw line goes only where the codec can say what it does.
void EncoderTest::codecsRefuseRawLinesTheyCannotVouchFor()
{
    const auto refusalOf = [](Dialect d, QByteArray line) {
        const auto codec = Codec::forDialect(d);
        QString why;
        codec->feed(line + '\n', [&](const Message &m) {
            if (why.isEmpty())
                why = codec->rawLineRefusal(m);
        });
        return why;
    };
    QVERIFY(refusalOf(Dialect::Rotctld, "w AZ10").contains(QStringLiteral("not a rotctld command")));
    QVERIFY(refusalOf(Dialect::Rotctld, "P 10 20").isEmpty());
    QVERIFY(refusalOf(Dialect::Gs232B, "O+1x").contains(QStringLiteral("not a relative move")));
    QVERIFY(refusalOf(Dialect::Gs232B, "W100 020").isEmpty());
    QVERIFY(refusalOf(Dialect::Micro2g, "M400").contains(QStringLiteral("not a Micro-2g go-to")));
    QVERIFY(refusalOf(Dialect::Easycomm3, "AZ10.0 EL20.0").isEmpty());
}

QTEST_GUILESS_MAIN(EncoderTest)
#include "tst_encoder.moc"
