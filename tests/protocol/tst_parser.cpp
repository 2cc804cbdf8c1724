// SPDX-License-Identifier: GPL-3.0-or-later
// The incremental parser against byte vectors: every row of the Easycomm command reference and
// the Easycomm III derivative, the strings Hamlib and SatNOGS put on the wire, tolerant numbers,
// chunking invariance and garbage recovery.

#include "messagedump.h"
#include "protocol/parser.h"

#include <QRandomGenerator>
#include <QTest>

using namespace slew::protocol;

class ParserTest : public QObject {
    Q_OBJECT
private slots:
    void vectors_data();
    void vectors();
    void easycomm1IsStrictAboutDecimals();
    void spaceEndedTokenWaitsForTheNextByte();
    void flushEndsALine();
    void chunkingGivesTheSameMessages_data();
    void chunkingGivesTheSameMessages();
    void garbageThenAValidReply();
    void overlongTokenIsDroppedOnce();
    void nulBytesAreRefused();
    void parseTokenWithoutContext();
    void rotctldPositionAnswerComesWhole();
    void rotctldBadInputChangesNothing_data();
    void rotctldBadInputChangesNothing();
    void rotctldChunkingGivesTheSameMessages();
};

void ParserTest::vectors_data()
{
    QTest::addColumn<QByteArray>("dialect");
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QStringList>("expected");

    auto row = [](const char *name, const char *dialect, const char *bytes, QStringList expected) {
        QTest::newRow(name) << QByteArray(dialect) << QByteArray(bytes) << expected;
    };

    // --- the Easycomm command reference, Easycomm I: the one-line command and the matching report.
    row("std1 line", "easycomm1", "AZ123.1 EL123.1 UP1231231231 LSB DN1231231231 USB\n",
        {"azimuth=123.1", "elevation=123.1", "uplink frequency=1231231231", "uplink mode 'LSB'",
         "downlink frequency=1231231231", "downlink mode 'USB'|"});
    row("std1 hamlib 201", "easycomm1", "AZ10.5 EL20.2 UP000 XXX DN000 XXX\n",
        {"azimuth=10.5", "elevation=20.2", "uplink frequency=0", "uplink mode 'XXX'", "downlink frequency=0",
         "downlink mode 'XXX'|"});
    row("std1 mode CW is a mode", "easycomm2", "UP145800000 CW DN435000000 FM\n",
        {"uplink frequency=145800000", "uplink mode 'CW'", "downlink frequency=435000000", "downlink mode 'FM'|"});

    // --- the Easycomm command reference, Easycomm II rows: command and response.
    row("AZ set", "easycomm2", "AZ123.1\n", {"azimuth=123.1|"});
    row("AZ get", "easycomm2", "AZ\n", {"azimuth|"});
    row("EL set", "easycomm2", "EL123.1\n", {"elevation=123.1|"});
    row("EL get", "easycomm2", "EL\n", {"elevation|"});
    row("UP set", "easycomm2", "UP1231231231\n", {"uplink frequency=1231231231|"});
    row("UP get", "easycomm2", "UP\n", {"uplink frequency|"});
    row("DN set", "easycomm2", "DN1231231231\n", {"downlink frequency=1231231231|"});
    row("DN get", "easycomm2", "DN\n", {"downlink frequency|"});
    row("DM set", "easycomm2", "DMLSB DMAM DM-\n",
        {"downlink mode 'LSB'", "downlink mode 'AM'", "downlink mode '-'|"});
    row("DM get", "easycomm2", "DM\n", {"downlink mode|"});
    row("UM set", "easycomm2", "UMUSB UMCW UM-\n", {"uplink mode 'USB'", "uplink mode 'CW'", "uplink mode '-'|"});
    row("UM get", "easycomm2", "UM\n", {"uplink mode|"});
    row("DR set", "easycomm2", "DR999\n", {"downlink radio=999|"});
    row("DR get", "easycomm2", "DR\n", {"downlink radio|"});
    row("UR set", "easycomm2", "UR999\n", {"uplink radio=999|"});
    row("UR get", "easycomm2", "UR\n", {"uplink radio|"});
    row("ML", "easycomm2", "ML\n", {"move left|"});
    row("MR", "easycomm2", "MR\n", {"move right|"});
    row("MU", "easycomm2", "MU\n", {"move up|"});
    row("MD", "easycomm2", "MD\n", {"move down|"});
    row("SA", "easycomm2", "SA\n", {"stop azimuth|"});
    row("SE", "easycomm2", "SE\n", {"stop elevation|"});
    row("AO", "easycomm2", "AO\n", {"acquisition of signal|"});
    row("LO", "easycomm2", "LO\n", {"loss of signal|"});
    row("OP", "easycomm2", "OP0,1 OP999,0\n", {"set output#0=1 '1'", "set output#999=0 '0'|"});
    row("IP get", "easycomm2", "IP0 IP1 IP2 IP3 IP999\n", {"input#0", "input#1", "input#2", "input#3", "input#999|"});
    row("IP reply", "easycomm2", "IP0,0 IP1,1 IP2,1.141 IP3,- IP999,asdf\n",
        {"input#0=0 '0'", "input#1=1 '1'", "input#2=1.141 '1.141'", "input#3 '-'", "input#999 'asdf'|"});
    row("AN get", "easycomm2", "AN0 AN999\n", {"analogue input#0", "analogue input#999|"});
    row("AN reply", "easycomm2", "AN0,65535 AN999,0\n",
        {"analogue input#0=65535 '65535'", "analogue input#999=0 '0'|"});
    row("ST set", "easycomm2", "ST22:01:19:02:30:16\n", {"time '22:01:19:02:30:16'|"});
    row("ST get", "easycomm2", "ST\n", {"time|"});
    row("VE get", "easycomm2", "VE\n", {"version|"});
    row("VE reply", "easycomm2", "VE0.123\n", {"version '0.123'|"});
    row("AL alarm", "easycomm2", "ALJAM_AZ\n", {"alarm 'JAM_AZ'|"});

    // --- the Easycomm command reference, Easycomm III rows.
    row("VL set", "easycomm3", "VL123\n", {"velocity left=123|"});
    row("VL get", "easycomm3", "VL\n", {"velocity left|"});
    row("VR", "easycomm3", "VR123 VR\n", {"velocity right=123", "velocity right|"});
    row("VU", "easycomm3", "VU123 VU\n", {"velocity up=123", "velocity up|"});
    row("VD", "easycomm3", "VD123 VD\n", {"velocity down=123", "velocity down|"});
    row("CR get", "easycomm3", "CR1\n", {"config read#1|"});
    row("CR reply", "easycomm3", "CR1,0 CR1,123.1 CR2,adsf\n",
        {"config read#1=0 '0'", "config read#1=123.1 '123.1'", "config read#2 'adsf'|"});
    row("CW", "easycomm3", "CW1,0 CW1,123.1 CW2,adsf\n",
        {"config write#1=0 '0'", "config write#1=123.1 '123.1'", "config write#2 'adsf'|"});
    row("GS get", "easycomm3", "GS\n", {"status register|"});
    row("GS reply", "easycomm3", "GS1 GS9\n", {"status register=1", "status register=9|"});
    row("GE get", "easycomm3", "GE\n", {"error register|"});
    row("GE reply", "easycomm3", "GE1 GE5\n", {"error register=1", "error register=5|"});

    // --- the Easycomm III derivative: commands.
    row("000 AZ two decimals", "easycomm3", "AZ123.45\n", {"azimuth=123.45|"});
    row("000 EL two decimals", "easycomm3", "EL45.67\n", {"elevation=45.67|"});
    row("000 VL four digits", "easycomm3", "VL1500 VR0250\n", {"velocity left=1500", "velocity right=250|"});
    row("000 SA SE", "easycomm3", "SA SE\n", {"stop azimuth", "stop elevation|"});
    row("000 RESET", "easycomm3", "RESET\n", {"reset and home|"});
    row("000 PARK", "easycomm3", "PARK\n", {"park|"});
    row("000 CW1..CW8", "easycomm3", "CW1,1.5 CW2,0.1 CW3,0.05 CW4,2 CW5,0 CW6,0.2 CW7,180 CW8,90\n",
        {"config write#1=1.5 '1.5'", "config write#2=0.1 '0.1'", "config write#3=0.05 '0.05'",
         "config write#4=2 '2'", "config write#5=0 '0'", "config write#6=0.2 '0.2'", "config write#7=180 '180'",
         "config write#8=90 '90'|"});
    row("000 ENC query", "easycomm3", "\\?ENC\n", {"raw encoders|"});
    // --- the Easycomm III derivative: status reports.
    row("000 AZ report", "easycomm3", "AZ154.1\n", {"azimuth=154.1|"});
    row("000 IP0..IP8", "easycomm3", "IP0,25.31\nIP1,1\nIP2,2\nIP3,123.45\nIP4,45.00\nIP5,12.5\nIP6,3\nIP7,1.5\nIP8,-2.0\n",
        {"input#0=25.31 '25.31'|", "input#1=1 '1'|", "input#2=2 '2'|", "input#3=123.45 '123.45'|",
         "input#4=45 '45.00'|", "input#5=12.5 '12.5'|", "input#6=3 '3'|", "input#7=1.5 '1.5'|",
         "input#8=-2 '-2.0'|"});
    row("000 VE report", "easycomm3", "VESlewSim-1.0\n", {"version 'SlewSim-1.0'|"});
    row("000 GS per axis", "easycomm3", "GS1030\n", {"status register=1030|"}); // el 4 << 8 | az 6
    row("000 GE", "easycomm3", "GE1\n", {"error register=1|"});
    row("000 CR10..13", "easycomm3", "CR10,123.45 CR11,45.00 CR12,1.50 CR13,0.00\n",
        {"config read#10=123.45 '123.45'", "config read#11=45 '45.00'", "config read#12=1.5 '1.50'",
         "config read#13=0 '0.00'|"});
    row("000 ENC report", "easycomm3", "\\?ENC123450,45000,-5,0\n", {"raw encoders=123450,45000,-5,0|"});

    // --- Peers (docs/protocol.md): what Hamlib and SatNOGS put on the wire.
    row("hamlib 202 set_pos", "easycomm2", "AZ10.5 EL20.2\n", {"azimuth=10.5", "elevation=20.2|"});
    row("hamlib 4.5 get_pos", "easycomm2", "AZ EL \n", {"azimuth", "elevation|"});
    row("hamlib 4.6 get_pos", "easycomm2", "AZ\nEL\n", {"azimuth|", "elevation|"});
    row("hamlib stop", "easycomm2", "SA SE \n", {"stop azimuth", "stop elevation|"});
    row("hamlib park reset", "easycomm2", "PARK\nRESET\n", {"park|", "reset and home|"});
    row("hamlib 204 move", "satnogs", "VR4900\nVU0100\n", {"velocity right=4900|", "velocity up=100|"});
    row("hamlib get_conf stray ;", "satnogs", "GS\n;GE\n;VE\n;CR 1\n;CW1,0.5\n;",
        {"status register|", "error register|", "version|", "config read#1|", "config write#1=0.5 '0.5'|"});
    row("one-line position reply", "easycomm2", "AZ10.0 EL20.0\n", {"azimuth=10", "elevation=20|"});
    row("hamlib dummy AZ reply", "easycomm2", "AZ10.0\nEL20.0\n", {"azimuth=10|", "elevation=20|"});
    row("satnogs CR n reply", "satnogs", "1,0.80\n", {"config value#1=0.8 '0.80'|"});
    row("satnogs VE", "satnogs", "VESatNOGS-v2.2\n", {"version 'SatNOGS-v2.2'|"});
    row("CRLF", "easycomm2", "AZ1.0\r\nEL2.0\r\n", {"azimuth=1|", "elevation=2|"});
    row("CR only", "easycomm2", "AZ1.0\rEL2.0\r", {"azimuth=1|", "elevation=2|"});

    // --- Tolerant numbers seen in the field.
    row("leading zeros", "easycomm2", "AZ000.1 EL00099\n", {"azimuth=0.1", "elevation=99|"});
    row("negative azimuth", "easycomm2", "AZ-0.4\n", {"azimuth=-0.4|"});
    row("comma decimal", "easycomm2", "AZ12,5\n", {"azimuth=12.5|"});
    row("lower case", "easycomm2", "az12.5 el3\n", {"azimuth=12.5", "elevation=3|"});

    // --- Refused tokens become Invalid with the raw text, and parsing goes on.
    row("unknown", "easycomm2", "XY12 AZ1\n", {"unreadable input 'XY12'", "azimuth=1|"});
    row("bad angle", "easycomm2", "AZ1x2\n", {"unreadable input 'AZ1x2'|"});
    row("bare with argument", "easycomm2", "SA1\n", {"unreadable input 'SA1'|"});
    row("CW without value", "easycomm3", "CW1\n", {"unreadable input 'CW1'|"});
    row("CR without register", "easycomm3", "CR\n", {"unreadable input 'CR'|"});
    row("CR then word", "satnogs", "CR GS\n", {"unreadable input 'CR'", "status register|"});
    row("negative velocity", "easycomm3", "VL-5\n", {"unreadable input 'VL-5'|"});
    row("bad time", "easycomm2", "ST12:00\n", {"unreadable input 'ST12:00'|"});
    row("velocity too large", "easycomm3", "VL99999999999999999999\n", {"unreadable input 'VL99999999999999999999'|"});
    row("velocity past 32 bits", "easycomm3", "VL2147483648\n", {"unreadable input 'VL2147483648'|"});
    row("velocity one over", "satnogs", "VR100000\n", {"unreadable input 'VR100000'|"});
    row("velocity at the top", "satnogs", "VR99999\n", {"velocity right=99999|"});
    row("time out of range", "easycomm2", "ST99:99:99:99:99:99\n", {"unreadable input 'ST99:99:99:99:99:99'|"});
    row("time month 13", "easycomm2", "ST26:13:01:00:00:00\n", {"unreadable input 'ST26:13:01:00:00:00'|"});
    row("time 30 February", "easycomm2", "ST26:02:30:00:00:00\n", {"unreadable input 'ST26:02:30:00:00:00'|"});
    row("time 29 February, leap year", "easycomm2", "ST28:02:29:23:59:59\n", {"time '28:02:29:23:59:59'|"});
    row("time 29 February, common year", "easycomm2", "ST27:02:29:00:00:00\n", {"unreadable input 'ST27:02:29:00:00:00'|"});
    row("time hour 24", "easycomm2", "ST26:11:21:24:00:00\n", {"unreadable input 'ST26:11:21:24:00:00'|"});
    row("time second 60", "easycomm2", "ST26:11:21:23:59:60\n", {"unreadable input 'ST26:11:21:23:59:60'|"});
    row("output not boolean", "easycomm2", "OP1,7\n", {"unreadable input 'OP1,7'|"});
    row("bare number", "easycomm2", "42\n", {"unreadable input '42'|"});

    // --- K3NG's Easycom firmware (its own source, built and run): each
    // query's answer is ended by the byte that ended the query, so `AZ EL\n`
    // is answered `+59.1 +24.8\n`, a set `AZ94.0 EL25.0\n` with just its
    // separators, and a command it lacks (PARK, GS, CR1) with `?`.
    row("bare pair (K3NG Easycom)", "easycomm2", "+59.1 +24.8\n", {"azimuth=59.1", "elevation=24.8|"});
    row("bare pair, elevation below the horizon", "easycomm2", "+0.0 -0.5\n", {"azimuth=0", "elevation=-0.5|"});
    row("bare pair, one per line", "easycomm2", "+359.9 +90.0\n+1.0 +2.0\n",
        {"azimuth=359.9", "elevation=90|", "azimuth=1", "elevation=2|"});
    row("bare pair in pieces of a line", "easycomm2", "+59.1 \n+24.8\n", {"azimuth=59.1|", "azimuth=24.8|"});
    row("separators only (K3NG's answer to a set)", "easycomm2", " \n", {});
    row("bare numbers broken", "easycomm2", "+ -x +5.5.5 +1e3\n",
        {"unreadable input '+'", "unreadable input '-x'", "unreadable input '+5.5.5'", "unreadable input '+1e3'|"});
    row("refusal (K3NG Easycom)", "easycomm2", "?\n", {"refusal '?'|"});
    row("refusal, Yaesu prompt on Easycomm", "satnogs", "?>\r\n", {"refusal '?>'|"});
    row("encoders short", "easycomm3", "\\?ENC1,2\n", {"unreadable input '\\?ENC1,2'|"});

    // --- GS-232A/B (Hamlib models 601, 603; the easycom library), commands.
    row("gs232 W", "gs232a", "W010 020\r", {"azimuth=10", "elevation=20|"});
    row("gs232 W without el", "gs232a", "W010\r", {"unreadable input 'W'|"});
    row("gs232 W then command", "gs232a", "W010 S\r",
        {"unreadable input 'W'", "stop azimuth", "stop elevation|"});
    row("gs232 M", "gs232b", "M123\r", {"azimuth=123|"});
    row("gs232 C C2 B", "gs232b", "C\rC2\rB\r", {"azimuth|", "azimuth", "elevation|", "elevation|"});
    row("gs232 S A E", "gs232a", "S\rA\rE\r", {"stop azimuth", "stop elevation|", "stop azimuth|", "stop elevation|"});
    row("gs232 moves", "gs232a", "R\rL\rU\rD\r", {"move right|", "move left|", "move up|", "move down|"});
    row("gs232 speed", "gs232b", "X2\rX5\r", {"speed=2|", "unreadable input 'X5'|"});
    row("the easycom library A E set", "gs232a", "A090\rE045\r", {"azimuth=90|", "elevation=45|"});
    row("the easycom library keep-alive", "gs232a", "?\r", {"keep-alive|"});
    row("keep-alive answer (Slew's choice)", "gs232b", "OK\r\n", {"keep-alive 'OK'|"});
    // The easycom library's relative move O+nnn+nnn, and the variants read.
    row("gs232 relative move", "gs232a", "O+010-005\r", {"relative move#0=10", "relative move#1=-5|"});
    row("gs232 relative move, short and unsigned first", "gs232b", "o10+5\r",
        {"relative move#0=10", "relative move#1=5|"});
    row("gs232 relative move, zero", "gs232b", "O+000+000\r", {"relative move#0=0", "relative move#1=0|"});
    row("gs232 relative move, one offset", "gs232a", "O+010\r", {"unreadable input 'O+010'|"});
    row("gs232 relative move, beyond 450", "gs232a", "O+500+000\r", {"unreadable input 'O+500+000'|"});
    row("gs232 relative move, no digits", "gs232a", "O+-5\rO++\r",
        {"unreadable input 'O+-5'|", "unreadable input 'O++'|"});
    // The easycom library's status query GS; its answer ST=n is Slew's choice.
    row("gs232 status query", "gs232a", "GS\rgs\r", {"status register|", "status register|"});
    row("gs232 status answer", "gs232b", "ST=6\r\n", {"status register=6|"});
    row("gs232 status variants", "gs232a", "ST6\rst=006\rST=0x0A\rST=moving\rST=Idle\r",
        {"status register=6|", "status register=6|", "status register=10|", "status register=2|",
         "status register=1|"});
    row("gs232 status malformed", "gs232b", "ST=\rST=70000\rST=busy\rST=0x\r",
        {"unreadable input 'ST='|", "unreadable input 'ST=70000'|", "unreadable input 'ST=busy'|",
         "unreadable input 'ST=0x'|"});
    // --- GS-232 reports.
    row("gs232a C2 report", "gs232a", "+0123+0045\r", {"azimuth=123", "elevation=45|"});
    row("gs232a C report", "gs232a", "+0359\r\n", {"azimuth=359|"});
    row("gs232b C2 report", "gs232b", "AZ=010  EL=020\r", {"azimuth=10", "elevation=20|"});
    row("gs232b single", "gs232b", "AZ=350\rEL=005\r", {"azimuth=350|", "elevation=5|"});
    // K3NG's firmware in its GS-232B mode, its bytes on the wire for C2.
    row("gs232b C2 report joined (K3NG)", "gs232b", "AZ=059EL=025\r\n", {"azimuth=59", "elevation=25|"});
    row("gs232b C2 report joined, lower case", "gs232b", "az=359el=000\r", {"azimuth=359", "elevation=0|"});
    row("gs232b C2 report joined, broken", "gs232b", "AZ=EL=025\rAZ=059EL=\rAZ=059EL=-5\r",
        {"unreadable input 'AZ=EL=025'|", "unreadable input 'AZ=059EL='|", "unreadable input 'AZ=059EL=-5'|"});
    // The Yaesu prompt after a command it did not take: a refusal, which
    // ends the wait for that command.
    row("gs232 prompt", "gs232b", "?>\r\n", {"refusal '?>'|"});
    row("gs232 garbage", "gs232a", "+0x12\rQ\r", {"unreadable input '+0x12'|", "unreadable input 'Q'|"});

    // --- rotctld's answers, as Hamlib 4.5's rotctld writes them (its rotctld(1) manual page).
    row("rotctld p", "rotctld", "180.000000\n45.000000\n", {"azimuth=180", "elevation=45|"});
    row("rotctld p two decimals", "rotctld", "0.00\n1.81\n", {"azimuth=0", "elevation=1.81|"});
    row("rotctld p negative", "rotctld", "-12.50\n0.00\n", {"azimuth=-12.5", "elevation=0|"});
    row("rotctld p crlf", "rotctld", "10.00\r\n20.00\r\n", {"azimuth=10", "elevation=20|"});
    row("rotctld done", "rotctld", "RPRT 0\n", {"rotctld report=0|"});
    row("rotctld rejected", "rotctld", "RPRT -9\n", {"alarm=-9 'RPRT -9: command rejected (RIG_ERJCTED)'|"});
    row("rotctld out of range", "rotctld", "RPRT -1\n", {"alarm=-1 'RPRT -1: invalid argument (RIG_EINVAL)'|"});
    row("rotctld limit", "rotctld", "RPRT -21\n", {"alarm=-21 'RPRT -21: limit exceeded (RIG_ELIMIT)'|"});
    row("rotctld unnamed code", "rotctld", "RPRT -42\n", {"alarm=-42 'RPRT -42: an error Hamlib does not name'|"});
    row("rotctld info", "rotctld", "Dummy rotator\n", {"version 'Dummy rotator'|"});
    row("rotctld answers in a row", "rotctld", "RPRT 0\n10.00\n20.00\nRPRT 0\n",
        {"rotctld report=0|", "azimuth=10", "elevation=20|", "rotctld report=0|"});
    // The commands Slew sends read back as their messages (the raw line's gate).
    row("rotctld set_pos", "rotctld", "P 10.5 20,25\n\\set_pos 1 2\n",
        {"azimuth=10.5", "elevation=20.25|", "azimuth=1", "elevation=2|"});
    row("rotctld get_pos", "rotctld", "p\n", {"azimuth", "elevation|"});
    row("rotctld stop park reset", "rotctld", "S\nK\nR 1\n\\park\n",
        {"stop azimuth", "stop elevation|", "park|", "reset and home|", "park|"});
    row("rotctld moves", "rotctld", "M 2 -1\nM 4 1\nM 8 100\n\\move 16 50\n",
        {"move up|", "move down|", "move left|", "move right|"});
    row("rotctld bad move", "rotctld", "M 3 50\nM 16 0\nM 16\n",
        {"unreadable input 'M 3 50'|", "unreadable input 'M 16 0'|", "unreadable input 'M 16'|"});
    row("rotctld unread commands", "rotctld", "\\dump_state\n+p\n;p\nq\n",
        {"unreadable input '\\dump_state'|", "unreadable input '+p'|", "unreadable input ';p'|",
         "unreadable input 'q'|"});
}

void ParserTest::vectors()
{
    QFETCH(QByteArray, dialect);
    QFETCH(QByteArray, bytes);
    QFETCH(QStringList, expected);
    Parser parser(*dialectFromName(QString::fromLatin1(dialect)));
    QCOMPARE(parseAll(parser, bytes), expected);
}

void ParserTest::easycomm1IsStrictAboutDecimals()
{
    Parser strict(Dialect::Easycomm1);
    QCOMPARE(parseAll(strict, "AZ123.12\n"), QStringList{"unreadable input 'AZ123.12'|"});
    Parser tolerant(Dialect::Easycomm3);
    QCOMPARE(parseAll(tolerant, "AZ123.12\n"), QStringList{"azimuth=123.12|"});
}

void ParserTest::spaceEndedTokenWaitsForTheNextByte()
{
    Parser parser(Dialect::Easycomm2);
    QVERIFY(parseAll(parser, "AZ10.0 ").isEmpty());
    QCOMPARE(parseAll(parser, "E"), QStringList{"azimuth=10"});
    QCOMPARE(parseAll(parser, "L20.0 "), QStringList{});
    QCOMPARE(parseAll(parser, "\n"), QStringList{"elevation=20|"});
}

void ParserTest::flushEndsALine()
{
    Parser parser(Dialect::Easycomm2);
    QVERIFY(parseAll(parser, "AZ10.0").isEmpty());
    QStringList out;
    parser.flush([&](const Message &m) { out << dumpMessage(m); });
    QCOMPARE(out, QStringList{"azimuth=10|"});
}

static QByteArray mixedTraffic()
{
    return "AZ123.1 EL123.1 UP1231231231 LSB DN1231231231 USB\n"
           "AZ10.0 EL20.0\nGS1030\nGE1\nIP0,25.31\nIP7,-1.5\nCR10,123.45\n1,0.80\n"
           "\\?ENC123450,45000,-5,0\r\nVESatNOGS-v2.2\r\nXY12 AZ-0.4 ;GE\n;CR 1\n AL_X  \n";
}

void ParserTest::chunkingGivesTheSameMessages_data()
{
    QTest::addColumn<quint32>("seed");
    for (quint32 seed : {1u, 2u, 3u, 4u, 5u, 99u})
        QTest::newRow(qPrintable(QString::number(seed))) << seed;
}

void ParserTest::chunkingGivesTheSameMessages()
{
    QFETCH(quint32, seed);
    const QByteArray bytes = mixedTraffic();
    Parser whole(Dialect::SatNogs);
    const QStringList expected = parseAll(whole, bytes);
    QVERIFY(expected.size() > 20);

    Parser single(Dialect::SatNogs);
    QStringList oneByOne;
    for (char c : bytes)
        oneByOne << parseAll(single, QByteArrayView(&c, 1));
    QCOMPARE(oneByOne, expected);

    QRandomGenerator random(seed);
    Parser chunked(Dialect::SatNogs);
    QStringList inChunks;
    for (qsizetype at = 0; at < bytes.size();) {
        const qsizetype n = qMin<qsizetype>(random.bounded(1, 17), bytes.size() - at);
        inChunks << parseAll(chunked, QByteArrayView(bytes).sliced(at, n));
        at += n;
    }
    QCOMPARE(inChunks, expected);
}

void ParserTest::garbageThenAValidReply()
{
    QRandomGenerator random(7);
    QByteArray garbage(64 * 1024, '\0');
    for (char &c : garbage)
        c = char(random.bounded(256));
    Parser parser(Dialect::Easycomm3);
    const QStringList junk = parseAll(parser, garbage);
    // At most one message per separator: the parser never invents input.
    const auto separators = std::count_if(garbage.begin(), garbage.end(),
                                          [](char c) { return c == ' ' || c == '\t' || c == ';' || c == '\r' || c == '\n'; });
    QVERIFY(junk.size() <= separators + 1);
    // Whatever the garbage left half-read, one line end puts the parser in sync.
    const QStringList after = parseAll(parser, "\nAZ10.0\n");
    QCOMPARE(after.last(), QStringLiteral("azimuth=10|"));
}

void ParserTest::overlongTokenIsDroppedOnce()
{
    Parser parser(Dialect::Easycomm3);
    const QByteArray huge(10 * 1024, 'A');
    QVERIFY(parseAll(parser, huge).isEmpty());
    const QStringList out = parseAll(parser, "\nGS1\n");
    QCOMPARE(out.size(), 2);
    QVERIFY(out[0].startsWith("unreadable input 'AAAA"));
    QCOMPARE(out[1], QStringLiteral("status register=1|"));

    // The reason says what happened.
    Parser again(Dialect::Easycomm3);
    const char *reason = nullptr;
    again.feed(huge + ' ', [](const Message &) {});
    again.feed("X", [&](const Message &m) { reason = m.reason; });
    QVERIFY(reason && QByteArray(reason).contains("longer than"));
    Refusal kind = Refusal::None;
    again.feed(QByteArray(200, 'B') + ' ', [](const Message &) {});
    again.feed("X", [&](const Message &m) { kind = m.refusal; });
    QCOMPARE(kind, Refusal::Overlong);

    // A bare CR waiting for its register, then an overlong token: both are
    // said, in order; the CR is not lost under the long one.
    Parser satnogs(Dialect::SatNogs);
    const QStringList both = parseAll(satnogs, "CR " + QByteArray(200, 'C') + "\n");
    QCOMPARE(both.size(), 2);
    QVERIFY2(both[0].contains("CR"), qPrintable(both.join(" / ")));
    QVERIFY2(both[1].startsWith("unreadable input 'CCCC"), qPrintable(both.join(" / ")));
}

void ParserTest::nulBytesAreRefused()
{
    Parser parser(Dialect::Easycomm3);
    const QByteArray bytes("AZ1\0\0\n EL2\n", 11);
    QCOMPARE(parseAll(parser, bytes), (QStringList{QStringLiteral("unreadable input 'AZ1") + QChar(0) + QChar(0) + "'|",
                                                   "elevation=2|"}));
}

void ParserTest::parseTokenWithoutContext()
{
    QCOMPARE(Parser::parseToken("XY12", Dialect::Easycomm3).refusal, Refusal::Unknown);
    QCOMPARE(Parser::parseToken("42", Dialect::Easycomm3).refusal, Refusal::Unknown);
    QCOMPARE(Parser::parseToken("AZ1x", Dialect::Easycomm3).refusal, Refusal::Malformed);
    QCOMPARE(Parser::parseToken("AZ1", Dialect::Easycomm3).refusal, Refusal::None);
    QCOMPARE(dumpMessage(Parser::parseToken("GS1030", Dialect::Easycomm3)), QStringLiteral("status register=1030"));
    QCOMPARE(Parser::parseToken("??", Dialect::Easycomm3).op, Op::Invalid);
    // Found by fuzz_parser: an empty token was read at its first byte.
    for (Dialect d : allDialects()) {
        const Message empty = Parser::parseToken("", d);
        QCOMPARE(empty.op, Op::Invalid);
        QCOMPARE(empty.refusal, Refusal::Unknown);
    }
}

void ParserTest::rotctldPositionAnswerComesWhole()
{
    // The azimuth line waits for its elevation: a half answer changes nothing.
    Parser parser(Dialect::Rotctld);
    QVERIFY(parseAll(parser, "180.000000\n").isEmpty());
    QVERIFY(parser.hasUnfinishedLine());
    QCOMPARE(parseAll(parser, "45.000000\n"), (QStringList{"azimuth=180", "elevation=45|"}));
    QVERIFY(!parser.hasUnfinishedLine());
    // reset() forgets a waiting azimuth.
    QVERIFY(parseAll(parser, "1.00\n").isEmpty());
    parser.reset();
    QCOMPARE(parseAll(parser, "2.00\n3.00\n"), (QStringList{"azimuth=2", "elevation=3|"}));
    // A lone number is an azimuth to parseToken, which has no line context.
    QCOMPARE(dumpMessage(Parser::parseToken("12.5", Dialect::Rotctld)), QStringLiteral("azimuth=12.5"));
}

void ParserTest::rotctldBadInputChangesNothing_data()
{
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QStringList>("expected");
    auto row = [](const char *name, QByteArray bytes, QStringList expected) {
        QTest::newRow(name) << bytes << expected;
    };
    row("garbage bytes", QByteArray("\x01\x02\xff\n", 4), {QStringLiteral("unreadable input '\x01\x02") + QChar(0xff) + "'|"});
    row("RPRT without a code", "RPRT\n", {"unreadable input 'RPRT'|"});
    row("RPRT with letters", "RPRT x\n", {"unreadable input 'RPRT x'|"});
    row("RPRT with a fraction", "RPRT -1.5\n", {"unreadable input 'RPRT -1.5'|"});
    row("RPRT too big", "RPRT -99999999999\n", {"unreadable input 'RPRT -99999999999'|"});
    row("RPRT and more", "RPRT 0 0\n", {"unreadable input 'RPRT 0 0'|"});
    row("a number with letters", "12abc\n", {"unreadable input '12abc'|"});
    // `p` answers with a line missing or not a number: both lines go,
    // with one message, and the next answer pairs up again.
    row("elevation not a number", "180.000000\nabc\n10\n20\n",
        {"unreadable input 'abc'|", "azimuth=10", "elevation=20|"});
    row("elevation malformed", "180.000000\n4x5\n10\n20\n",
        {"unreadable input '4x5'|", "azimuth=10", "elevation=20|"});
    row("azimuth malformed", "1x0\n45.000000\n10\n20\n",
        {"unreadable input '1x0'|", "azimuth=10", "elevation=20|"});
    row("elevation missing", "180.000000\nRPRT 0\n10\n20\n",
        {"unreadable input 'RPRT 0'|", "rotctld report=0|", "azimuth=10", "elevation=20|"});
    row("azimuth malformed, elevation missing", "1x0\nRPRT -1\n",
        {"unreadable input '1x0'|", "alarm=-1 'RPRT -1: invalid argument (RIG_EINVAL)'|"});
}

void ParserTest::rotctldBadInputChangesNothing()
{
    QFETCH(QByteArray, bytes);
    QFETCH(QStringList, expected);
    Parser parser(Dialect::Rotctld);
    QStringList reasons;
    QStringList out;
    parser.feed(bytes, [&](const Message &m) {
        out << dumpMessage(m);
        if (m.op == Op::Invalid)
            reasons << QString::fromLatin1(m.reason);
    });
    QCOMPARE(out, expected);
    // Each refusal says why, and a good line after it reads as before.
    for (const QString &reason : std::as_const(reasons))
        QVERIFY2(reason.size() > 10, qPrintable(reason));
    QCOMPARE(parseAll(parser, "RPRT 0\n"), QStringList{"rotctld report=0|"});
}

void ParserTest::rotctldChunkingGivesTheSameMessages()
{
    const QByteArray bytes = "RPRT 0\n180.000000\n45.000000\nDummy rotator\nRPRT -9\n"
                             "1x0\n2\nP 1 2\n" + QByteArray(300, 'Z') + "\n10.00\r\n20.00\r\n";
    Parser whole(Dialect::Rotctld);
    const QStringList expected = parseAll(whole, bytes);
    QCOMPARE(expected.size(), 11);
    QVERIFY(expected[8].startsWith("unreadable input 'ZZZ"));
    QRandomGenerator random(11);
    Parser chunked(Dialect::Rotctld);
    QStringList inChunks;
    for (qsizetype at = 0; at < bytes.size();) {
        const qsizetype n = qMin<qsizetype>(random.bounded(1, 9), bytes.size() - at);
        inChunks << parseAll(chunked, QByteArrayView(bytes).sliced(at, n));
        at += n;
    }
    QCOMPARE(inChunks, expected);
}

QTEST_GUILESS_MAIN(ParserTest)
#include "tst_parser.moc"
