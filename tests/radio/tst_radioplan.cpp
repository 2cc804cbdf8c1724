// SPDX-License-Identifier: GPL-3.0-or-later
// What a radio is tuned to: a frequency as an operator writes it, the plan
// made from a transponder (the passband's middle, the paired uplink, the
// modes), and the station service's radio options resolved against
// transponder files (by name, by default, refusals that say why).

#include "radio/radioplan.h"
#include "station/radiooptions.h"

#include <QTest>

#include <limits>

using namespace slew::radio;
using slew::station::RadioOptions;
using slew::station::resolveRadioPlan;

namespace {

const QString kData = QStringLiteral(SLEW_TEST_DATA_DIR "/transponders/");

} // namespace

class RadioPlanTest : public QObject {
    Q_OBJECT
private slots:
    void frequenciesAsOperatorsWriteThem_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<double>("hz");
        QTest::newRow("megahertz") << "145.8M" << 145.8e6;
        QTest::newRow("MHz with a space") << "435.125 MHz" << 435.125e6;
        QTest::newRow("kilohertz") << "1296200k" << 1296.2e6;
        QTest::newRow("gigahertz") << "10.368G" << 10.368e9;
        QTest::newRow("hertz") << "437800000" << 437.8e6;
        QTest::newRow("Hz spelled out") << "437800000Hz" << 437.8e6;
        QTest::newRow("rounded to the hertz") << "145.8000004M" << 145.8e6;
        QTest::newRow("low case") << "145.8mhz" << 145.8e6;
    }
    void frequenciesAsOperatorsWriteThem()
    {
        QFETCH(QString, text);
        QFETCH(double, hz);
        QString error;
        const std::optional<double> read = parseFrequency(text, &error);
        QVERIFY2(read, qPrintable(error));
        QCOMPARE(*read, hz);
    }

    void notFrequencies_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("says");
        QTest::newRow("empty") << "" << "is not a frequency";
        QTest::newRow("nan") << "nan" << "is not a frequency";
        QTest::newRow("inf") << "infM" << "is not a frequency";
        QTest::newRow("overflow") << "1e999" << "is not a frequency";
        QTest::newRow("a word") << "two metres" << "is not a frequency";
        QTest::newRow("megahertz without a unit") << "145.8" << "write the unit (145.8M";
        QTest::newRow("negative") << "-145.8M" << "outside";
        QTest::newRow("zero") << "0" << "outside";
        QTest::newRow("above the spectrum") << "400G" << "outside";
        QTest::newRow("control characters") << "145\x1b[2J" << "is not a frequency";
    }
    void notFrequencies()
    {
        QFETCH(QString, text);
        QFETCH(QString, says);
        QString error;
        QVERIFY(!parseFrequency(text, &error));
        QVERIFY2(error.contains(says), qPrintable(error));
        QVERIFY(!error.contains(QChar(0x1b))); // the terminal is not reached through a message
    }

    void offsetsAreSignedAndSmall()
    {
        QString error;
        QCOMPARE(parseFrequencyOffset("-1.2k", &error).value_or(0), -1200.0);
        QCOMPARE(parseFrequencyOffset("350", &error).value_or(0), 350.0);
        QVERIFY(!parseFrequencyOffset("2M", &error));
        QVERIFY2(error.contains("outside"), qPrintable(error));
        QVERIFY(!parseFrequencyOffset("nan", &error));
    }

    void anInvertingLinearTransponderIsTunedToItsMiddle()
    {
        Transponder t;
        t.noradId = 24278;
        t.description = "Mode V/U linear";
        t.uplinkLowHz = 145.900e6;
        t.uplinkHighHz = 146.000e6;
        t.downlinkLowHz = 435.800e6;
        t.downlinkHighHz = 435.900e6;
        t.mode = "SSB/CW";
        t.inverting = true;
        QString note, error;
        const std::optional<RadioPlan> plan = planFor(t, &note, &error);
        QVERIFY(plan);
        QCOMPARE(plan->frequencies.downlinkHz, 435.850e6);
        QCOMPARE(plan->frequencies.uplinkHz.value_or(0), 145.950e6); // the middle maps to the middle
        QCOMPARE(plan->frequencies.uplinkFollows, UplinkFollowsDial::OppositeWay);
        QCOMPARE(plan->receiveMode, QString("USB"));
        QCOMPARE(plan->transmitMode, QString("LSB")); // turned over by the transponder
        QCOMPARE(plan->noradId, 24278);
        QVERIFY(note.isEmpty());
        // Its passband, where the operator may tune from the window; found
        // again for a downlink typed by hand inside it, not outside.
        QVERIFY(plan->frequencies.downlinkPassband);
        QCOMPARE(plan->frequencies.downlinkPassband->lowHz, 435.8e6);
        QCOMPARE(plan->frequencies.downlinkPassband->highHz, 435.9e6);
        QCOMPARE(passbandAround({t}, 435.812e6).value_or(Passband{}).highHz, 435.9e6);
        QVERIFY(!passbandAround({t}, 435.95e6));
    }

    void aRepeaterIsTunedToItsChannels()
    {
        Transponder t;
        t.noradId = 25544;
        t.uplinkLowHz = 145.990e6;
        t.downlinkLowHz = 437.800e6;
        t.mode = "fm";
        QString note, error;
        const std::optional<RadioPlan> plan = planFor(t, &note, &error);
        QVERIFY(plan);
        QCOMPARE(plan->frequencies.downlinkHz, 437.8e6);
        QCOMPARE(plan->frequencies.uplinkHz.value_or(0), 145.99e6);
        QCOMPARE(plan->frequencies.uplinkFollows, UplinkFollowsDial::No);
        QCOMPARE(plan->receiveMode, QString("FM"));
        QCOMPARE(plan->transmitMode, QString("FM"));
        QVERIFY(!plan->frequencies.downlinkPassband); // a channel: nothing to tune across
        QVERIFY(!passbandAround({t}, 437.8e6));
    }

    void aModeWithoutAHamlibNameIsLeftAlone()
    {
        Transponder t;
        t.downlinkLowHz = 437.025e6;
        t.mode = "GMSK";
        QString note, error;
        const std::optional<RadioPlan> plan = planFor(t, &note, &error);
        QVERIFY(plan);
        QVERIFY(plan->receiveMode.isEmpty());
        QVERIFY2(note.contains("'GMSK' has no Hamlib name"), qPrintable(note));
        Transponder uplinkOnly;
        uplinkOnly.uplinkLowHz = 145.9e6;
        QVERIFY(!planFor(uplinkOnly, &note, &error));
        QVERIFY2(error.contains("no downlink"), qPrintable(error));
    }

    void serviceOptionsPickATransponder()
    {
        RadioOptions options;
        options.transponderFiles = {kData + "satnogs-transmitters.json", kData + "24278.trsp"};
        QStringList notes;
        QString error;
        // FO-29's default: its first alive linear transponder, from the .trsp file.
        std::optional<RadioPlan> plan = resolveRadioPlan(options, 24278, &notes, &error);
        QVERIFY2(plan, qPrintable(error));
        QCOMPARE(plan->name, QString("Mode V/U linear"));
        // By name, with the calibration offsets and the choice of paths on top.
        options.transponderName = "cw bea";
        options.downlinkOffsetHz = -1200;
        options.correct = DopplerOn::DownlinkOnly;
        options.downlinkMode = "CWR";
        plan = resolveRadioPlan(options, 24278, &notes, &error);
        QVERIFY2(plan, qPrintable(error));
        QCOMPARE(plan->frequencies.downlinkHz, 435.795e6);
        QCOMPARE(plan->frequencies.downlinkOffsetHz, -1200.0);
        QCOMPARE(plan->frequencies.correct, DopplerOn::DownlinkOnly);
        QCOMPARE(plan->receiveMode, QString("CWR"));
        // A name it does not have: the ones it has are listed.
        options.transponderName = "Mode U/V";
        QVERIFY(!resolveRadioPlan(options, 24278, &notes, &error));
        QVERIFY2(error.contains("no transponder of NORAD 24278 is named 'Mode U/V'") && error.contains("'CW beacon'"),
                 qPrintable(error));
        // A satellite with none.
        options.transponderName.clear();
        QVERIFY(!resolveRadioPlan(options, 99999, &notes, &error));
        QVERIFY2(error.contains("no transponder for NORAD 99999"), qPrintable(error));
    }

    void serviceOptionsByHand()
    {
        RadioOptions options;
        options.downlinkHz = 437.8e6;
        options.uplinkHz = 145.99e6;
        QStringList notes;
        QString error;
        const std::optional<RadioPlan> plan = resolveRadioPlan(options, 25544, &notes, &error);
        QVERIFY(plan);
        QCOMPARE(plan->noradId, 25544);
        QCOMPARE(plan->frequencies.uplinkHz.value_or(0), 145.99e6);
        // The uplink alone needs an uplink.
        RadioOptions downOnly;
        downOnly.downlinkHz = 437.8e6;
        downOnly.correct = DopplerOn::UplinkOnly;
        QVERIFY(!resolveRadioPlan(downOnly, 25544, &notes, &error));
        QVERIFY2(error.contains("no uplink"), qPrintable(error));
        // Nothing at all.
        QVERIFY(!resolveRadioPlan(RadioOptions{}, 25544, &notes, &error));
        QVERIFY2(error.contains("needs its frequencies"), qPrintable(error));
    }

    void aBadTransponderFileIsRefusedWhole()
    {
        RadioOptions options;
        options.transponderFiles = {kData + "no-such-file.json"};
        QStringList notes;
        QString error;
        QVERIFY(!resolveRadioPlan(options, 25544, &notes, &error));
        QVERIFY2(error.contains("no-such-file.json"), qPrintable(error));
        // One with bad entries: the good ones are used, the bad ones noted.
        options.transponderFiles = {kData + "satnogs-transmitters-bad.json"};
        const std::optional<RadioPlan> plan = resolveRadioPlan(options, 25544, &notes, &error);
        QVERIFY2(plan, qPrintable(error));
        QVERIFY(!notes.isEmpty());
    }

    void modeNamesAndChoices()
    {
        QString error;
        QCOMPARE(slew::radio::parseModeName(" usb ", &error).value_or(""), QString("USB"));
        QVERIFY(!slew::radio::parseModeName("USB 2400", &error));
        QVERIFY(!slew::radio::parseModeName("USB\nq", &error));
        QVERIFY(!slew::radio::parseModeName("", &error));
        QCOMPARE(slew::station::parseDopplerOn("Uplink", &error).value_or(DopplerOn::Both), DopplerOn::UplinkOnly);
        QVERIFY(!slew::station::parseDopplerOn("up", &error));
        QCOMPARE(slew::station::parseUplinkFollows("opposite", &error).value_or(UplinkFollowsDial::No),
                 UplinkFollowsDial::OppositeWay);
        QVERIFY(!slew::station::parseUplinkFollows("yes", &error));
        QVERIFY2(error.contains("no, same or opposite"), qPrintable(error));
    }
};

QTEST_GUILESS_MAIN(RadioPlanTest)
#include "tst_radioplan.moc"
