// SPDX-License-Identifier: GPL-3.0-or-later
// The micro2g dialect's codec: the commands of the Micro-2g program's header
// comment as Slew writes them, and the answers (Slew's choice of format,
// docs/protocol.md "Micro-2g") with the variants the reader accepts. The
// vectors are the document's own examples where it gives them (M035, the
// rotor digits, P/L presets).

#include "messagedump.h"

#include "protocol/dialect.h"
#include "protocol/encoder.h"
#include "protocol/parser.h"

#include <QTest>

using namespace slew::protocol;

class Micro2gCodecTest : public QObject {
    Q_OBJECT
private slots:
    void named()
    {
        QCOMPARE(dialectFromName(u"micro2g"), std::optional<Dialect>(Dialect::Micro2g));
        QCOMPARE(dialectName(Dialect::Micro2g), QStringLiteral("micro2g"));
        QCOMPARE(lineTerminator(Dialect::Micro2g), '\r');
    }

    void supportsWhatTheProgramHas()
    {
        const Dialect m = Dialect::Micro2g;
        for (Op op : {Op::Azimuth, Op::StopAzimuth, Op::Preset, Op::StorePreset, Op::SelectRotor, Op::Version,
                      Op::Tolerance, Op::Calibration, Op::AdcReadings, Op::RelayBits})
            QVERIFY2(dialectSupports(m, op), describe(op));
        // No elevation axis, no speeds, no registers, no park or homing.
        for (Op op : {Op::Elevation, Op::StopElevation, Op::VelocityLeft, Op::VelocityUp, Op::MoveLeft, Op::MoveUp,
                      Op::ConfigRead, Op::ConfigWrite, Op::Status, Op::ErrorFlags, Op::Park, Op::Reset, Op::Offset,
                      Op::KeepAlive, Op::Speed, Op::ReadInput, Op::Encoders})
            QVERIFY2(!dialectSupports(m, op), describe(op));
    }

    void encodesTheDocumentsCommands()
    {
        const Dialect m = Dialect::Micro2g;
        // "turn rotor to 35 degrees: M035"
        QCOMPARE(encodeSetPosition(35, 0, m), QByteArray("M035\r"));
        // A named rotor is made the default first: M has no rotor digit.
        QCOMPARE(encodeSetPosition(35, 0, m, 2), QByteArray("2\rM035\r"));
        // A mechanical azimuth in the overlap is the bearing it points to.
        QCOMPARE(encodeSetPosition(400, 0, m, 1), QByteArray("1\rM040\r"));
        QCOMPARE(encodeQueryPosition(m), QByteArray("C\r"));
        QCOMPARE(encodeQueryPosition(m, 3), QByteArray("C3\r"));
        QCOMPARE(encodeStop(true, false, m), QByteArray("S\r"));
        QCOMPARE(encodeStop(true, true, m, 4), QByteArray("S4\r"));
        QVERIFY(encodeStop(false, true, m, 4).isEmpty()); // no elevation to stop
        QCOMPARE(encodeLine({Message::number(Op::Preset, 2)}, m), QByteArray("P2\r"));
        QCOMPARE(encodeLine({Message::number(Op::Preset, 3, 2)}, m), QByteArray("P23\r"));
        QCOMPARE(encodeLine({Message::number(Op::StorePreset, 1)}, m), QByteArray("L1\r"));
        QCOMPARE(encodeLine({Message::number(Op::StorePreset, 1, 4)}, m), QByteArray("L41\r"));
        QCOMPARE(encodeLine({Message::number(Op::SelectRotor, 3)}, m), QByteArray("3\r"));
        QCOMPARE(encodeLine({Message::query(Op::Version)}, m), QByteArray("?\r"));
        QCOMPARE(encodeLine({Message::query(Op::Tolerance)}, m), QByteArray("T\r"));
        QCOMPARE(encodeLine({Message::number(Op::Tolerance, 20, 1)}, m), QByteArray("T1 20\r"));
        QCOMPARE(encodeLine({Message::query(Op::Calibration)}, m), QByteArray("Z\r"));
        // The document's examples: the north-stop setup.
        QCOMPARE(encodeLine({Message::word(Op::Calibration, "L 3990=000", 1)}, m), QByteArray("Z1L 3990=000\r"));
        QCOMPARE(encodeLine({Message::word(Op::Calibration, "R 2440=090", 1)}, m), QByteArray("Z1R 2440=090\r"));
        QCOMPARE(encodeLine({Message::word(Op::Calibration, "D 450", 1)}, m), QByteArray("Z1D 450\r"));
        QCOMPARE(encodeLine({Message::query(Op::AdcReadings)}, m), QByteArray("V\r"));
        QCOMPARE(encodeLine({Message::query(Op::RelayBits)}, m), QByteArray("R\r"));
        QVERIFY(encodeLine({Message::number(Op::Tolerance, 501, 1)}, m).isEmpty());
        QVERIFY(encodeLine({Message::number(Op::Tolerance, 20)}, m).isEmpty()); // Tn x names the rotor
        // Out of the program's ranges: nothing.
        QVERIFY(encodeLine({Message::number(Op::Preset, 4)}, m).isEmpty());
        QVERIFY(encodeLine({Message::number(Op::SelectRotor, 5)}, m).isEmpty());
        QVERIFY(encodeLine({Message::number(Op::Elevation, 10)}, m).isEmpty());
        QVERIFY(encodeLine({Message::number(Op::VelocityLeft, 100)}, m).isEmpty());
        QVERIFY(encodeLine({Message::query(Op::ConfigRead, 1)}, m).isEmpty());
    }

    void parses_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QStringList>("expected");
        auto row = [](const char *name, const char *bytes, const QStringList &expected) {
            QTest::newRow(name) << QByteArray(bytes) << expected;
        };
        // Answers: a heading (Slew's `+0123`, and the variants read).
        row("heading", "+0123\r\n", {"azimuth=123", "elevation=0|"});
        row("heading variants", "+123\r123\r  +0045  \r123.5\r",
            {"azimuth=123", "elevation=0|", "azimuth=123", "elevation=0|", "azimuth=45", "elevation=0|",
             "azimuth=123.5", "elevation=0|"});
        row("heading naming the rotor", "C2=+0270\rc=090\r", {"azimuth#2=270", "elevation=0|", "azimuth=90", "elevation=0|"});
        row("heading out of range", "+0400\r+0x12\r", {"unreadable input '+0400'|", "unreadable input '+0x12'|"});
        row("refusal", "?> unknown command 'Q'\r\n", {"alarm 'unknown command 'Q''|"});
        row("bare refusal", "?>\r", {"alarm '?>'|"});
        row("information", "Micro-2g rotor controller: 4 rotors, default rotor 1, 0 turning, 9600 8N1\r\n",
            {"version 'Micro-2g rotor controller: 4 rotors, default rotor 1, 0 turning, 9600 8N1'|"});
        // The listings (Slew's forms, and the variants read).
        row("tolerances", "T1=20 T2=20 T3=20 T4=20\r", {"tolerance 'T1=20 T2=20 T3=20 T4=20'|"});
        row("tolerances, lower case and commas", "t1=20,t2=35, t3=5\r", {"tolerance 'T1=20 T2=35 T3=5'|"});
        row("A/D readings", "V1=3990 V2=2440 V3=0 V4=4095\r", {"A/D readings 'V1=3990 V2=2440 V3=0 V4=4095'|"});
        row("relay bits", "R1=- R2=L R3=r R4=-\r", {"relay bits 'R1=- R2=L R3=R R4=-'|"});
        row("listings malformed", "T1=x\rV5=1\rR1=Q\r",
            {"unreadable input 'T1=x'|", "unreadable input 'V5=1'|", "unreadable input 'R1=Q'|"});
        row("calibration answer", "Z1L 3990=000 Z1R 2440=090 Z1D 450\r",
            {"calibration#1 'Z1L 3990=000 Z1R 2440=090 Z1D 450'|"});
        // The document's setups, as commands.
        row("north stop setup", "Z1L 3990=000\rZ1R 2440=090\rZ1D 450\r",
            {"calibration#1 'L 3990=000'|", "calibration#1 'R 2440=090'|", "calibration#1 'D 450'|"});
        row("south stop setup", "Z1L 3990=180\rZ1R 2440=270\r", {"calibration#1 'L 3990=180'|", "calibration#1 'R 2440=270'|"});
        row("calibrate at the present reading", "z2l 045\rZ2R 135\r", {"calibration#2 'L 045'|", "calibration#2 'R 135'|"});
        row("calibration malformed", "Z5L 000\rZ1Q 000\rZ1D 4500\rZ1L 39900=000\r",
            {"unreadable input 'Z5L 000'|", "unreadable input 'Z1Q 000'|", "unreadable input 'Z1D 4500'|",
             "unreadable input 'Z1L 39900=000'|"});
        row("listing queries", "T\rZ\rV\rR\r", {"tolerance|", "calibration|", "A/D readings|", "relay bits|"});
        row("set tolerance", "T1 20\rT4 500\rT2 0\rT9 5\r",
            {"tolerance#1=20|", "tolerance#4=500|", "unreadable input 'T2 0'|", "unreadable input 'T9 5'|"});
        // Commands, as a host sends them (the raw-line gate reads these).
        row("select rotor", "2\r5\r", {"select rotor=2|", "unreadable input '5'|"});
        row("heading queries", "C\rC3\rc\r", {"azimuth|", "azimuth#3|", "azimuth|"});
        row("go-to", "M035\rX4rM180\rX4M090\r", {"azimuth=35|", "azimuth=180|", "azimuth=90|"});
        row("go-to malformed", "M35\rM361\rMabc\r",
            {"unreadable input 'M35'|", "unreadable input 'M361'|", "unreadable input 'Mabc'|"});
        row("presets", "P1\rP23\rL2\rL41\r",
            {"go to preset=1|", "go to preset#2=3|", "store preset=2|", "store preset#4=1|"});
        row("preset malformed", "P4\rP53\r", {"unreadable input 'P4'|", "unreadable input 'P53'|"});
        row("stop", "S\rS4\r", {"stop azimuth|", "stop azimuth#4|"});
        row("information query", "?\r", {"version|"});
        row("overlong", QByteArray(200, 'Z').append('\r').constData(),
            {QStringLiteral("unreadable input '%1'|").arg(QString(128, u'Z'))});
    }

    void parses()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(QStringList, expected);
        Parser whole(Dialect::Micro2g);
        QCOMPARE(parseAll(whole, bytes), expected);
        // Byte by byte, the same.
        Parser bytewise(Dialect::Micro2g);
        QStringList out;
        for (char c : bytes)
            out += parseAll(bytewise, QByteArrayView(&c, 1));
        QCOMPARE(out, expected);
    }
};

QTEST_MAIN(Micro2gCodecTest)
#include "tst_micro2gcodec.moc"
