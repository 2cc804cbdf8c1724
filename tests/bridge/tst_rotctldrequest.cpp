// SPDX-License-Identifier: GPL-3.0-or-later
// Reading rotctld command lines and writing answers byte for byte as Hamlib
// 4.5's rotctld does (the expected strings were captured from `rotctld -m 1`).

#include "input/logtext.h"
#include "bridge/positionanswer.h"
#include "bridge/rotctldrequest.h"

#include <QTest>

#include <limits>

using namespace slew::bridge;
using Kind = RotctldRequest::Kind;

Q_DECLARE_METATYPE(RotctldRequest::Kind)

class RotctldRequestTest : public QObject {
    Q_OBJECT
private slots:
    void logTextIsEscapedAndCut()
    {
        using slew::input::loggableText;
        QCOMPARE(loggableText("P 10 20"), QString("P 10 20"));
        QCOMPARE(loggableText(QString::fromLatin1("a\x1b[2Jb\x07\x7f\x9b")), QString("a\\x1b[2Jb\\x07\\x7f\\x9b"));
        QCOMPARE(loggableText(QString(250, 'x')), QString(200, 'x') + QString::fromUtf8("… (50 more bytes)"));
        // An escape is never cut in half.
        const QString cut = loggableText(QString(198, 'x') + QChar(0x1b) + "y", 200);
        QCOMPARE(cut, QString(198, 'x') + QString::fromUtf8("… (2 more bytes)"));
    }

    void logAllowanceIsABurstThenARate()
    {
        slew::input::LogAllowance a;
        int allowed = 0;
        for (int i = 0; i < 100; ++i)
            allowed += a.take(0);
        QCOMPARE(allowed, 20);
        QCOMPARE(a.takeSuppressed(), 80);
        QCOMPARE(a.takeSuppressed(), 0);
        QVERIFY(a.take(500)); // two a second
        QVERIFY(!a.take(500));
        QCOMPARE(a.suppressed(), 1);
    }

    void parse_data();
    void parse();
    void answers();
    void errorsAreNamed();
    void hugeAnglesAreAnsweredWhole();
    void aKeptPositionAnswerIsTheFormattedOne();
};

void RotctldRequestTest::parse_data()
{
    QTest::addColumn<QByteArray>("line");
    QTest::addColumn<Kind>("kind");
    QTest::addColumn<bool>("extended");
    QTest::addColumn<char>("separator");
    QTest::addColumn<double>("az");
    QTest::addColumn<double>("el");
    QTest::newRow("p") << QByteArray("p") << Kind::GetPosition << false << '\n' << 0.0 << 0.0;
    QTest::newRow("P") << QByteArray("P 10 20") << Kind::SetPosition << false << '\n' << 10.0 << 20.0;
    QTest::newRow("P gpredict") << QByteArray("P 180.25 45.50") << Kind::SetPosition << false << '\n' << 180.25 << 45.5;
    QTest::newRow("P comma") << QByteArray("P 10,5 20,5") << Kind::SetPosition << false << '\n' << 10.5 << 20.5;
    QTest::newRow("P netrotctl") << QByteArray("P 10.000000 20.000000") << Kind::SetPosition << false << '\n' << 10.0 << 20.0;
    QTest::newRow("set_pos") << QByteArray("\\set_pos 1 2") << Kind::SetPosition << false << '\n' << 1.0 << 2.0;
    QTest::newRow("+set_pos") << QByteArray("+\\set_pos 1 2") << Kind::SetPosition << true << '\n' << 1.0 << 2.0;
    QTest::newRow("get_pos") << QByteArray("\\get_pos") << Kind::GetPosition << false << '\n' << 0.0 << 0.0;
    QTest::newRow("+get_pos") << QByteArray("+\\get_pos") << Kind::GetPosition << true << '\n' << 0.0 << 0.0;
    QTest::newRow(";get_pos") << QByteArray(";\\get_pos") << Kind::GetPosition << true << ';' << 0.0 << 0.0;
    QTest::newRow("|p") << QByteArray("|p") << Kind::GetPosition << true << '|' << 0.0 << 0.0;
    QTest::newRow("S") << QByteArray("S") << Kind::Stop << false << '\n' << 0.0 << 0.0;
    QTest::newRow("stop") << QByteArray("\\stop") << Kind::Stop << false << '\n' << 0.0 << 0.0;
    QTest::newRow("K") << QByteArray("K") << Kind::Park << false << '\n' << 0.0 << 0.0;
    QTest::newRow("park") << QByteArray("\\park") << Kind::Park << false << '\n' << 0.0 << 0.0;
    QTest::newRow("R") << QByteArray("R 1") << Kind::Reset << false << '\n' << 0.0 << 0.0;
    QTest::newRow("reset") << QByteArray("\\reset 1") << Kind::Reset << false << '\n' << 0.0 << 0.0;
    QTest::newRow("M") << QByteArray("M 16 50") << Kind::Move << false << '\n' << 0.0 << 0.0;
    QTest::newRow("move") << QByteArray("\\move 2 10") << Kind::Move << false << '\n' << 0.0 << 0.0;
    QTest::newRow("_") << QByteArray("_") << Kind::GetInfo << false << '\n' << 0.0 << 0.0;
    QTest::newRow("get_info") << QByteArray("\\get_info") << Kind::GetInfo << false << '\n' << 0.0 << 0.0;
    QTest::newRow("dump_state") << QByteArray("\\dump_state") << Kind::DumpState << false << '\n' << 0.0 << 0.0;
    QTest::newRow("q") << QByteArray("q") << Kind::Quit << false << '\n' << 0.0 << 0.0;
    QTest::newRow("CRLF trimmed") << QByteArray("p\r") << Kind::GetPosition << false << '\n' << 0.0 << 0.0;
    QTest::newRow("unknown short") << QByteArray("Z") << Kind::Unknown << false << '\n' << 0.0 << 0.0;
    QTest::newRow("unknown long") << QByteArray("\\fly_to_moon") << Kind::Unknown << false << '\n' << 0.0 << 0.0;
    QTest::newRow("P one arg") << QByteArray("P 10") << Kind::Malformed << false << '\n' << 0.0 << 0.0;
    QTest::newRow("P not number") << QByteArray("P abc 20") << Kind::Malformed << false << '\n' << 0.0 << 0.0;
    QTest::newRow("P inf") << QByteArray("P inf 20") << Kind::Malformed << false << '\n' << 0.0 << 0.0;
    QTest::newRow("M not number") << QByteArray("M up 50") << Kind::Malformed << false << '\n' << 0.0 << 0.0;
    QTest::newRow("bare +") << QByteArray("+") << Kind::Malformed << true << '\n' << 0.0 << 0.0;
}

void RotctldRequestTest::parse()
{
    QFETCH(QByteArray, line);
    QFETCH(Kind, kind);
    QFETCH(bool, extended);
    QFETCH(char, separator);
    QFETCH(double, az);
    QFETCH(double, el);
    const RotctldRequest r = parseRotctldLine(line);
    QCOMPARE(r.kind, kind);
    QCOMPARE(r.extended, extended);
    QCOMPARE(r.separator, separator);
    if (kind == Kind::SetPosition) {
        QCOMPARE(r.az, az);
        QCOMPARE(r.el, el);
    }
    if (kind == Kind::Unknown || kind == Kind::Malformed)
        QVERIFY(!r.error.isEmpty());
}

void RotctldRequestTest::answers()
{
    // Captured from Hamlib 4.5's rotctld -m 1.
    QCOMPARE(formatPosition(parseRotctldLine("p"), 0, 0), QByteArray("0.00\n0.00\n"));
    QCOMPARE(formatPosition(parseRotctldLine("p"), 123.4, 45.6), QByteArray("123.40\n45.60\n"));
    QCOMPARE(formatPosition(parseRotctldLine("+\\get_pos"), 0.01, 0.01),
             QByteArray("get_pos:\nAzimuth: 0.01\nElevation: 0.01\nRPRT 0\n"));
    QCOMPARE(formatPosition(parseRotctldLine(";\\get_pos"), 0.01, 0.01),
             QByteArray("get_pos:;Azimuth: 0.01;Elevation: 0.01;RPRT 0\n"));
    QCOMPARE(formatPosition(parseRotctldLine("|\\get_pos"), 0, 0),
             QByteArray("get_pos:|Azimuth: 0.00|Elevation: 0.00|RPRT 0\n"));
    QCOMPARE(formatStatus(parseRotctldLine("P 10 20"), 0), QByteArray("RPRT 0\n"));
    QCOMPARE(formatStatus(parseRotctldLine("P 500 20"), 1), QByteArray("RPRT -1\n"));
    QCOMPARE(formatStatus(parseRotctldLine("+\\set_pos 10 20"), 0), QByteArray("set_pos: 10 20\nRPRT 0\n"));
    QCOMPARE(formatStatus(parseRotctldLine("+\\move 16 50"), 0), QByteArray("move: 16 50\nRPRT 0\n"));
    QCOMPARE(formatStatus(parseRotctldLine("+\\stop"), 0), QByteArray("stop:\nRPRT 0\n"));
    QCOMPARE(formatStatus(parseRotctldLine("+\\park"), 0), QByteArray("park:\nRPRT 0\n"));
    QCOMPARE(formatStatus(parseRotctldLine("+\\reset 1"), 0), QByteArray("reset: 1\nRPRT 0\n"));
    QCOMPARE(formatInfo(parseRotctldLine("_"), "Dummy rotator"), QByteArray("Dummy rotator\n"));
    QCOMPARE(formatInfo(parseRotctldLine("+\\get_info"), "Dummy rotator"),
             QByteArray("get_info:\nInfo: Dummy rotator\nRPRT 0\n"));
    QCOMPARE(formatDumpState({-180, 450, 0, 90, 1}),
             QByteArray("1\n1\nmin_az=-180.000000\nmax_az=450.000000\nmin_el=0.000000\nmax_el=90.000000\n"
                        "south_zero=0\nrot_type=AzEl\ndone\n"));
    QCOMPARE(formatStatus(parseRotctldLine("Z"), 1), QByteArray("RPRT -1\n"));
}

void RotctldRequestTest::errorsAreNamed()
{
    QCOMPARE(describeHamlibError(-9), QStringLiteral("command rejected"));
    QCOMPARE(describeHamlibError(1), QStringLiteral("invalid argument"));
    QCOMPARE(describeHamlibError(-21), QStringLiteral("limit exceeded"));
    QVERIFY(describeHamlibError(-99).contains("99"));
    QVERIFY(describeHamlibError(std::numeric_limits<int>::min()).contains("-2147483648"));
}

// Found by fuzz_rotctldrequest (seed `P 1e308 1e-308`): snprintf returned the
// length 1e308 needs, far more than the 48-byte buffer, and the answer copied
// the stack beyond it. A rotctld:// peer can report such an angle, and
// set_pos accepts one (the limits refuse it later).
void RotctldRequestTest::hugeAnglesAreAnsweredWhole()
{
    const RotctldRequest r = parseRotctldLine("P 1e308 1e-308");
    QCOMPARE(r.kind, Kind::SetPosition);
    const QByteArray answer = formatPosition(parseRotctldLine("p"), r.az, r.el);
    const QList<QByteArray> lines = answer.split('\n');
    QCOMPARE(lines.size(), 3);
    QCOMPARE(lines[0].size(), 309 + 3);
    QVERIFY(lines[0].startsWith("1000000000000000010979"));
    QVERIFY(lines[0].endsWith(".00"));
    QCOMPARE(lines[1], QByteArray("0.00"));
    const QByteArray state = formatDumpState({-1.7976931348623157e308, 1.7976931348623157e308, 0, 90, 1});
    QVERIFY(state.contains("\nmin_az=-17976931348623157"));
    QVERIFY(state.contains(".000000\nmax_az=17976931348623157"));
    QVERIFY(state.endsWith("done\n"));
}

// PositionAnswer hands the next asker the answer it formatted for the
// last: whatever the positions, the request or their order, it is
// formatPosition's.
void RotctldRequestTest::aKeptPositionAnswerIsTheFormattedOne()
{
    PositionAnswer kept;
    const RotctldRequest plain = parseRotctldLine("p");
    const RotctldRequest extended = parseRotctldLine("+\\get_pos");
    const RotctldRequest separated = parseRotctldLine(";\\get_pos");
    const double positions[][2] = {{0, 0}, {0, 0}, {-0.0, 0}, {0, -0.0}, {0, 0}, {123.4, 45.6}, {123.4, 45.6},
                                   {123.404, 45.6}, {359.996, 90}, {1e308, 1e-308}, {0.004, 0}, {-0.004, 0}};
    for (const auto &at : positions) {
        for (const RotctldRequest *r : {&plain, &extended, &plain, &separated, &plain}) {
            QCOMPARE(kept.answer(*r, at[0], at[1]), formatPosition(*r, at[0], at[1]));
        }
    }
    QCOMPARE(kept.answer(plain, -0.0, 0), QByteArray("-0.00\n0.00\n"));
    QCOMPARE(kept.answer(plain, 0.0, 0), QByteArray("0.00\n0.00\n"));
}

QTEST_GUILESS_MAIN(RotctldRequestTest)
#include "tst_rotctldrequest.moc"
