// SPDX-License-Identifier: GPL-3.0-or-later
// Transponders: the uplink that pairs with a downlink on a linear
// transponder, the set by satellite and its default, and the two importers
// (SatNOGS DB's transmitter list, Gpredict's .trsp files) on samples
// written in their formats and on bad input: each bad entry skipped with a
// message naming the source, the entry and the field, the good ones kept,
// and a source with nothing usable refused.

#include "radio/transponder.h"
#include "radio/transponderimport.h"
#include "radio/transponderset.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <limits>

using namespace slew::radio;

namespace {

const QString kData = QStringLiteral(SLEW_TEST_DATA_DIR "/transponders/");

// A linear transponder like FO-29's: 145.900-146.000 MHz up, 435.800-435.900
// MHz down, inverting.
Transponder invertingLinear()
{
    Transponder t;
    t.noradId = 24278;
    t.description = QStringLiteral("Mode V/U linear");
    t.uplinkLowHz = 145.900e6;
    t.uplinkHighHz = 146.000e6;
    t.downlinkLowHz = 435.800e6;
    t.downlinkHighHz = 435.900e6;
    t.mode = QStringLiteral("SSB");
    t.inverting = true;
    return t;
}

// Like AO-7's mode A: 145.850-145.950 MHz up, 29.400-29.500 MHz down, not
// inverting.
Transponder nonInvertingLinear()
{
    Transponder t;
    t.noradId = 7530;
    t.description = QStringLiteral("Mode A linear");
    t.uplinkLowHz = 145.850e6;
    t.uplinkHighHz = 145.950e6;
    t.downlinkLowHz = 29.400e6;
    t.downlinkHighHz = 29.500e6;
    t.mode = QStringLiteral("SSB");
    return t;
}

Transponder beacon(int norad, double hz, const QString &description = QStringLiteral("beacon"))
{
    Transponder t;
    t.noradId = norad;
    t.description = description;
    t.downlinkLowHz = hz;
    t.mode = QStringLiteral("CW");
    return t;
}

// One SatNOGS DB entry, good, with `field` set to the raw JSON `value`
// (or removed, for an empty value).
QByteArray satnogsEntry(const QByteArray &field = {}, const QByteArray &value = {})
{
    QList<QPair<QByteArray, QByteArray>> fields{
        {"uuid", "\"SlwTest000000000000001\""}, {"description", "\"voice\""}, {"alive", "true"},
        {"type", "\"Transceiver\""},           {"uplink_low", "145990000"},   {"uplink_high", "null"},
        {"downlink_low", "437800000"},         {"downlink_high", "null"},     {"mode", "\"FM\""},
        {"invert", "false"},                   {"baud", "null"},              {"norad_cat_id", "25544"},
        {"status", "\"active\""}};
    QByteArray out = "{";
    bool found = false;
    for (const auto &[name, raw] : fields) {
        QByteArray v = raw;
        if (name == field) {
            found = true;
            if (value.isEmpty())
                continue;
            v = value;
        }
        if (out.size() > 1)
            out += ", ";
        out += '"' + name + "\": " + v;
    }
    if (!found && !field.isEmpty())
        out += ", \"" + field + "\": " + value;
    return out + '}';
}

QByteArray satnogsList(const QList<QByteArray> &entries)
{
    return '[' + entries.join(",\n") + ']';
}

QString firstSkip(const TransponderImport &read)
{
    return read.skipped.value(0);
}

} // namespace

class TestTransponders : public QObject {
    Q_OBJECT
private slots:
    // The value
    void linearMeansAPassbandOnTheDownlink();
    void uplinkForDownlinkInverting();
    void uplinkForDownlinkNotInverting();
    void noPairingOutsideThePassband_data();
    void noPairingOutsideThePassband();
    void downlinkForUplinkIsTheInverse();

    // The set
    void setKeepsEachSatellitesTransponders();
    void mergeDropsRepeatsAcrossSources();
    void defaultIsTheFirstAliveLinear();
    void mergeTakesTimeInTheCount();

    // SatNOGS DB
    void satnogsSampleReads();
    void satnogsBadEntriesAreSkippedNamingTheField_data();
    void satnogsBadEntriesAreSkippedNamingTheField();
    void satnogsMessageNamesSourceEntryAndField();
    void satnogsFileKeepsTheGoodEntries();
    void satnogsTextInMessagesIsEscaped();
    void satnogsNumbersAsTextAndZeroAsNone();
    void satnogsAliveFollowsStatusWhenMissing();
    void satnogsWholeSourceRefusals_data();
    void satnogsWholeSourceRefusals();
    void satnogsDeepNestingIsRefused();
    void skipMessagesAreCapped();

    // Gpredict
    void trspSamplesRead();
    void trspNoradIdFromFileName_data();
    void trspNoradIdFromFileName();
    void trspBadGroupsAreSkippedNamingTheField_data();
    void trspBadGroupsAreSkippedNamingTheField();
    void trspFileKeepsTheGoodGroups();
    void trspGroupsMergeAndLastKeyWins();
    void trspWholeSourceRefusals_data();
    void trspWholeSourceRefusals();

    // Files
    void filesThatAreNotFilesAreRefused();
    void filesOverTheCapAreRefused();
    void bothSourcesMergeIntoOneSet();
};

// ---- The value ---------------------------------------------------------

void TestTransponders::linearMeansAPassbandOnTheDownlink()
{
    QVERIFY(invertingLinear().isLinear());
    QVERIFY(nonInvertingLinear().isLinear());
    QVERIFY(!beacon(24278, 435.795e6).isLinear());
    Transponder same = beacon(24278, 435.795e6);
    same.downlinkHighHz = 435.795e6;
    QVERIFY(!same.isLinear());
    // A passband on the uplink alone is not a linear transponder.
    Transponder uplinkOnly;
    uplinkOnly.uplinkLowHz = 145.9e6;
    uplinkOnly.uplinkHighHz = 146.0e6;
    QVERIFY(!uplinkOnly.isLinear());
}

void TestTransponders::uplinkForDownlinkInverting()
{
    const Transponder t = invertingLinear();
    // The middle maps to the middle; the bottom of the downlink to the top of
    // the uplink, and the other way round.
    QCOMPARE(t.uplinkForDownlink(435.850e6).value(), 145.950e6);
    QCOMPARE(t.uplinkForDownlink(435.800e6).value(), 146.000e6);
    QCOMPARE(t.uplinkForDownlink(435.900e6).value(), 145.900e6);
    QCOMPARE(t.uplinkForDownlink(435.810e6).value(), 145.990e6);
}

void TestTransponders::uplinkForDownlinkNotInverting()
{
    const Transponder t = nonInvertingLinear();
    QCOMPARE(t.uplinkForDownlink(29.450e6).value(), 145.900e6);
    QCOMPARE(t.uplinkForDownlink(29.400e6).value(), 145.850e6);
    QCOMPARE(t.uplinkForDownlink(29.500e6).value(), 145.950e6);
}

void TestTransponders::noPairingOutsideThePassband_data()
{
    QTest::addColumn<Transponder>("transponder");
    QTest::addColumn<double>("downlinkHz");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    QTest::newRow("below the passband") << invertingLinear() << 435.7999e6;
    QTest::newRow("above the passband") << invertingLinear() << 435.9001e6;
    QTest::newRow("nan") << invertingLinear() << nan;
    QTest::newRow("inf") << invertingLinear() << inf;
    QTest::newRow("-inf") << nonInvertingLinear() << -inf;
    QTest::newRow("a beacon") << beacon(24278, 435.795e6) << 435.795e6;
    Transponder noUplink = invertingLinear();
    noUplink.uplinkLowHz.reset();
    noUplink.uplinkHighHz.reset();
    QTest::newRow("no uplink") << noUplink << 435.85e6;
}

void TestTransponders::noPairingOutsideThePassband()
{
    QFETCH(Transponder, transponder);
    QFETCH(double, downlinkHz);
    QVERIFY(!transponder.uplinkForDownlink(downlinkHz));
}

void TestTransponders::downlinkForUplinkIsTheInverse()
{
    for (const Transponder &t : {invertingLinear(), nonInvertingLinear()}) {
        for (double f = *t.downlinkLowHz; f <= *t.downlinkHighHz; f += 10e3) {
            const std::optional<double> up = t.uplinkForDownlink(f);
            QVERIFY(up);
            QVERIFY(std::abs(t.downlinkForUplink(*up).value() - f) < 1e-3);
        }
        QVERIFY(!t.downlinkForUplink(*t.uplinkLowHz - 1e3));
        QVERIFY(!t.downlinkForUplink(*t.uplinkHighHz + 1e3));
        QVERIFY(!t.downlinkForUplink(std::numeric_limits<double>::quiet_NaN()));
    }
}

// ---- The set -----------------------------------------------------------

void TestTransponders::setKeepsEachSatellitesTransponders()
{
    TransponderSet set;
    QVERIFY(set.isEmpty());
    QCOMPARE(set.merge({beacon(24278, 435.795e6), invertingLinear(), nonInvertingLinear()}), 0);
    QCOMPARE(set.size(), 3);
    QCOMPARE(set.satellites(), (QList<int>{7530, 24278}));
    const QList<Transponder> fo29 = set.forSatellite(24278);
    QCOMPARE(fo29.size(), 2);
    QCOMPARE(fo29[0].description, QStringLiteral("beacon"));
    QCOMPARE(fo29[1].description, QStringLiteral("Mode V/U linear"));
    QVERIFY(set.forSatellite(25544).isEmpty());
}

void TestTransponders::mergeDropsRepeatsAcrossSources()
{
    TransponderSet set;
    Transponder fromSatnogs = invertingLinear();
    fromSatnogs.uuid = QStringLiteral("SlwTest000000000000001");
    QCOMPARE(set.merge({fromSatnogs}), 0);

    // The same entry again (a second copy of the list), with a changed
    // description: the one held stays.
    Transponder again = fromSatnogs;
    again.description = QStringLiteral("renamed");
    // The same transponder from a Gpredict file: no uuid, the same
    // frequencies, sense and mode in other letter case.
    Transponder fromGpredict = invertingLinear();
    fromGpredict.mode = QStringLiteral("ssb");
    fromGpredict.description = QStringLiteral("[Mode V/U linear]");
    // Not the same: another mode on the same frequencies, another satellite.
    Transponder otherMode = invertingLinear();
    otherMode.mode = QStringLiteral("CW");
    Transponder otherSatellite = invertingLinear();
    otherSatellite.noradId = 44909;
    QCOMPARE(set.merge({again, fromGpredict, otherMode, otherSatellite}), 2);
    QCOMPARE(set.size(), 3);
    QCOMPARE(set.forSatellite(24278).size(), 2);
    QCOMPARE(set.forSatellite(24278)[0].description, QStringLiteral("Mode V/U linear"));
    QCOMPARE(set.forSatellite(44909).size(), 1);
}

void TestTransponders::defaultIsTheFirstAliveLinear()
{
    Transponder deadLinear = nonInvertingLinear();
    deadLinear.noradId = 24278;
    deadLinear.alive = false;
    Transponder deadBeacon = beacon(24278, 435.795e6, QStringLiteral("dead beacon"));
    deadBeacon.alive = false;

    TransponderSet set;
    // The linear comes after a beacon and a dead linear, and still wins.
    set.merge({deadBeacon, beacon(24278, 435.796e6, QStringLiteral("alive beacon")), deadLinear, invertingLinear()});
    QCOMPARE(set.defaultFor(24278)->description, QStringLiteral("Mode V/U linear"));

    // No alive linear: the first alive of any kind.
    TransponderSet noLinear;
    noLinear.merge({deadBeacon, deadLinear, beacon(24278, 435.796e6, QStringLiteral("alive beacon"))});
    QCOMPARE(noLinear.defaultFor(24278)->description, QStringLiteral("alive beacon"));

    // Nothing alive: no default; an unknown satellite: none either.
    TransponderSet dead;
    dead.merge({deadBeacon, deadLinear});
    QVERIFY(!dead.defaultFor(24278));
    QVERIFY(!set.defaultFor(25544));
}

void TestTransponders::mergeTakesTimeInTheCount()
{
    // A list of many entries for one satellite (a file a user names can
    // hold anything up to its cap) merges in time in the count: comparing
    // each with all those held took minutes at this size.
    QList<Transponder> many;
    for (int i = 0; i < 100000; ++i)
        many << beacon(25544, 100e6 + i);
    QElapsedTimer timer;
    timer.start();
    TransponderSet set;
    QCOMPARE(set.merge(many), 0);
    QCOMPARE(set.merge(many), many.size());
    QCOMPARE(set.size(), many.size());
    QVERIFY2(timer.elapsed() < 20000, qPrintable(QString::number(timer.elapsed())));
}

// ---- SatNOGS DB --------------------------------------------------------

void TestTransponders::satnogsSampleReads()
{
    const TransponderImport read = readSatnogsTransmittersFile(kData + QStringLiteral("satnogs-transmitters.json"));
    QVERIFY2(read.ok(), qPrintable(read.error));
    QCOMPARE(read.skipReport(), QStringList());
    QCOMPARE(read.transponders.size(), 8);

    const Transponder &voice = read.transponders[0];
    QCOMPARE(voice.noradId, 25544);
    QCOMPARE(voice.description, QStringLiteral("Mode V/U FM voice repeater"));
    QCOMPARE(voice.uuid, QStringLiteral("SlwSample0000000000001"));
    QCOMPARE(voice.uplinkLowHz.value(), 145990000.0);
    QVERIFY(!voice.uplinkHighHz);
    QCOMPARE(voice.downlinkLowHz.value(), 437800000.0);
    QVERIFY(!voice.downlinkHighHz);
    QCOMPARE(voice.mode, QStringLiteral("FM"));
    QVERIFY(!voice.inverting);
    QVERIFY(voice.alive);
    QVERIFY(!voice.isLinear());

    const Transponder &fo29 = read.transponders[3];
    QCOMPARE(fo29.noradId, 24278);
    QVERIFY(fo29.isLinear());
    QVERIFY(fo29.inverting);
    QCOMPARE(fo29.uplinkForDownlink(435.850e6).value(), 145.950e6);

    const Transponder &deadBeacon = read.transponders[6];
    QCOMPARE(deadBeacon.noradId, 7530);
    QVERIFY(!deadBeacon.alive);
    QVERIFY(deadBeacon.mode.isEmpty()); // null in the list

    TransponderSet set;
    set.merge(read.transponders);
    QCOMPARE(set.satellites(), (QList<int>{7530, 24278, 25544, 44909}));
    QCOMPARE(set.defaultFor(7530)->description, QStringLiteral("Mode A linear"));
    QCOMPARE(set.defaultFor(24278)->description, QStringLiteral("Mode V/U linear"));
    QCOMPARE(set.defaultFor(25544)->description, QStringLiteral("Mode V/U FM voice repeater"));
}

void TestTransponders::satnogsBadEntriesAreSkippedNamingTheField_data()
{
    QTest::addColumn<QByteArray>("entry");
    QTest::addColumn<QString>("reason");

    const auto row = [](const char *tag, const QByteArray &entry, const char *reason) {
        QTest::newRow(tag) << entry << QString::fromUtf8(reason);
    };
    row("text, not a number", satnogsEntry("downlink_low", "\"abc\""), "downlink_low 'abc' is not a number");
    row("nan as text", satnogsEntry("downlink_low", "\"nan\""), "downlink_low 'nan' is not a finite number");
    row("inf as text", satnogsEntry("uplink_low", "\"inf\""), "uplink_low 'inf' is not a finite number");
    row("1e999 as text", satnogsEntry("uplink_high", "\"1e999\""), "uplink_high '1e999' is not a"); // Qt reads it as no number at all
    row("negative", satnogsEntry("downlink_low", "-437800000"), "downlink_low -437800000 Hz is negative");
    row("above 300 GHz", satnogsEntry("downlink_low", "4e12"), "downlink_low 4000000000000 Hz is above 300 GHz");
    row("low above high", satnogsEntry("downlink_high", "437700000"),
        "downlink_low 437800000 Hz is above downlink_high 437700000 Hz");
    row("a boolean frequency", satnogsEntry("uplink_low", "true"), "uplink_low is true, not a number");
    row("an array frequency", satnogsEntry("downlink_high", "[1]"), "downlink_high is an array, not a number");
    row("an object frequency", satnogsEntry("downlink_low", "{}"), "downlink_low is an object, not a number");
    row("no frequency", satnogsEntry("uplink_low", "null").replace("437800000", "null"),
        "no uplink or downlink frequency");
    row("catalogue number null", satnogsEntry("norad_cat_id", "null"), "no norad_cat_id");
    row("catalogue number missing", satnogsEntry("norad_cat_id"), "no norad_cat_id");
    row("catalogue number not whole", satnogsEntry("norad_cat_id", "25544.5"),
        "norad_cat_id 25544.5 is not a catalogue number");
    row("catalogue number negative", satnogsEntry("norad_cat_id", "-1"), "norad_cat_id -1 is not a catalogue number");
    row("catalogue number huge", satnogsEntry("norad_cat_id", "1e20"), "is not a catalogue number");
    row("catalogue number text", satnogsEntry("norad_cat_id", "\"ISS\""), "norad_cat_id 'ISS' is not a whole number");
    row("catalogue number boolean", satnogsEntry("norad_cat_id", "false"), "norad_cat_id is false, not a number");
    row("invert as text", satnogsEntry("invert", "\"yes\""), "invert is 'yes', not true or false");
    row("invert as number", satnogsEntry("invert", "1"), "invert is a number, not true or false");
    row("alive as text", satnogsEntry("alive", "\"true\""), "alive is 'true', not true or false");
    row("description a number", satnogsEntry("description", "5"), "description is a number, not text");
    row("mode an object", satnogsEntry("mode", "{\"name\": \"FM\"}"), "mode is an object, not text");
    row("a number, not an object", "7", "is a number, not a transmitter object");
    row("text, not an object", "\"FM\"", "is text, not a transmitter object");
    row("null, not an object", "null", "is null, not a transmitter object");
    row("an array, not an object", "[]", "is an array, not a transmitter object");
}

void TestTransponders::satnogsBadEntriesAreSkippedNamingTheField()
{
    QFETCH(QByteArray, entry);
    QFETCH(QString, reason);
    // A good entry before it and after it: both kept.
    const TransponderImport read
        = readSatnogsTransmitters(satnogsList({satnogsEntry(), entry, satnogsEntry("uuid", "\"SlwTest000000000000003\"")}),
                                  QStringLiteral("transmitters.json"));
    QVERIFY2(read.ok(), qPrintable(read.error));
    QCOMPARE(read.transponders.size(), 2);
    QCOMPARE(read.skippedCount, 1);
    QVERIFY2(firstSkip(read).startsWith(QStringLiteral("transmitters.json: entry 2")), qPrintable(firstSkip(read)));
    QVERIFY2(firstSkip(read).contains(reason), qPrintable(firstSkip(read)));
}

void TestTransponders::satnogsMessageNamesSourceEntryAndField()
{
    QList<QByteArray> entries;
    for (int i = 0; i < 11; ++i)
        entries << satnogsEntry("uuid", QByteArray("\"SlwTest0000000000000") + QByteArray::number(10 + i) + '"');
    entries << satnogsEntry("downlink_low", "\"abc\"").replace("\"voice\"", "\"ISS voice\"");
    const TransponderImport read = readSatnogsTransmitters(satnogsList(entries), QStringLiteral("transmitters.json"));
    QCOMPARE(read.skipped,
             QStringList{QStringLiteral("transmitters.json: entry 12 (ISS voice): downlink_low 'abc' is not a number")});
    QCOMPARE(read.transponders.size(), 11);
}

void TestTransponders::satnogsFileKeepsTheGoodEntries()
{
    const QString path = kData + QStringLiteral("satnogs-transmitters-bad.json");
    const TransponderImport read = readSatnogsTransmittersFile(path);
    QVERIFY2(read.ok(), qPrintable(read.error));
    QCOMPARE(read.transponders.size(), 2);
    QCOMPARE(read.transponders[0].description, QStringLiteral("FM voice"));
    QCOMPARE(read.transponders[1].description, QStringLiteral("CW beacon"));
    const QStringList expected{
        path + QStringLiteral(": entry 2 (voice): downlink_low 'abc' is not a number"),
        path + QStringLiteral(": entry 3 (far too high): downlink_low 4000000000000 Hz is above 300 GHz, the top of the "
                              "radio spectrum"),
        path + QStringLiteral(": entry 4 (upside down): uplink_low 146000000 Hz is above uplink_high 145900000 Hz"),
        path + QStringLiteral(": entry 5 (not yet catalogued): no norad_cat_id: the satellite has no catalogue number"),
        path + QStringLiteral(": entry 6: is text, not a transmitter object"),
    };
    QCOMPARE(read.skipped, expected);
    QCOMPARE(read.skippedCount, 5);
}

void TestTransponders::satnogsTextInMessagesIsEscaped()
{
    // An escape sequence in a description and in a value reaches no
    // terminal raw; a long description is cut.
    const QByteArray entry = satnogsEntry("downlink_low", "\"\\u001b[2J\"")
                                 .replace("\"voice\"", "\"\\u001b[31mred " + QByteArray(300, 'x') + "\"");
    const TransponderImport read = readSatnogsTransmitters(satnogsList({satnogsEntry(), entry}), QStringLiteral("t\x1b.json"));
    const QString message = firstSkip(read);
    QVERIFY2(!message.contains(QChar(0x1b)), qPrintable(message));
    QVERIFY2(message.startsWith(QStringLiteral("t\\x1b.json: entry 2 (\\x1b[31mred xxx")), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("downlink_low '\\x1b[2J' is not a number")), qPrintable(message));
    QVERIFY2(message.size() < 200, qPrintable(message));
}

void TestTransponders::satnogsNumbersAsTextAndZeroAsNone()
{
    // A frequency as text holding a number is read by the same rule; 0 is
    // no frequency (Gpredict writes an absent one as 0, and so do lists
    // converted from it).
    const QByteArray entry = satnogsEntry("downlink_low", "\"437800000\"").replace("145990000", "0");
    const TransponderImport read = readSatnogsTransmitters(satnogsList({entry}), QStringLiteral("t.json"));
    QVERIFY2(read.ok(), qPrintable(read.error));
    QCOMPARE(read.transponders.size(), 1);
    QCOMPARE(read.transponders[0].downlinkLowHz.value(), 437800000.0);
    QVERIFY(!read.transponders[0].uplinkLowHz);

    // A high edge alone is the single frequency.
    const QByteArray highOnly = satnogsEntry("downlink_high", "437800000").replace("\"downlink_low\": 437800000", "\"downlink_low\": null");
    const TransponderImport high = readSatnogsTransmitters(satnogsList({highOnly}), QStringLiteral("t.json"));
    QCOMPARE(high.transponders.size(), 1);
    QCOMPARE(high.transponders[0].downlinkLowHz.value(), 437800000.0);
    QVERIFY(!high.transponders[0].downlinkHighHz);
}

void TestTransponders::satnogsAliveFollowsStatusWhenMissing()
{
    const TransponderImport read = readSatnogsTransmitters(
        satnogsList({satnogsEntry("alive"), satnogsEntry("alive").replace("\"active\"", "\"inactive\""),
                     satnogsEntry("alive").replace("\"active\"", "\"invalid\""),
                     satnogsEntry("alive").replace(", \"status\": \"active\"", "")}),
        QStringLiteral("t.json"));
    QCOMPARE(read.transponders.size(), 4);
    QVERIFY(read.transponders[0].alive);
    QVERIFY(!read.transponders[1].alive);
    QVERIFY(!read.transponders[2].alive);
    QVERIFY(read.transponders[3].alive);
}

void TestTransponders::satnogsWholeSourceRefusals_data()
{
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QString>("reason");
    QTest::newRow("empty") << QByteArray() << "is not JSON";
    QTest::newRow("not JSON") << QByteArray("<html><body>502 Bad Gateway</body></html>") << "is not JSON";
    QTest::newRow("cut short") << satnogsList({satnogsEntry()}).chopped(5) << "is not JSON";
    QTest::newRow("an object") << QByteArray("{\"detail\": \"Not found.\"}") << "is a JSON object, not the array";
    QTest::newRow("a number") << QByteArray("42") << "is not JSON"; // Qt takes only an object or an array
    QTest::newRow("empty array") << QByteArray("[]") << "no transmitters in it";
    QTest::newRow("all bad") << satnogsList({"1", "2", satnogsEntry("norad_cat_id", "null")})
                             << "no usable transponder: all 3 transmitters were skipped";
    QTest::newRow("not UTF-8") << QByteArray("[{\"description\": \"\xff\xfe\"}]") << "is not UTF-8 text";
    QTest::newRow("NaN literal") << QByteArray("[{\"downlink_low\": NaN}]") << "is not JSON";
    // Qt's parser refuses a number past the doubles' range, so the whole
    // list is refused, not the entry.
    QTest::newRow("1e999") << satnogsList({satnogsEntry("downlink_low", "1e999")}) << "is not JSON: illegal number";
    QTest::newRow("Infinity literal") << QByteArray("[{\"downlink_low\": Infinity}]") << "is not JSON";
}

void TestTransponders::satnogsWholeSourceRefusals()
{
    QFETCH(QByteArray, bytes);
    QFETCH(QString, reason);
    const TransponderImport read = readSatnogsTransmitters(bytes, QStringLiteral("transmitters.json"));
    QVERIFY(!read.ok());
    QVERIFY(read.transponders.isEmpty());
    QVERIFY2(read.error.startsWith(QStringLiteral("transmitters.json: ")), qPrintable(read.error));
    QVERIFY2(read.error.contains(reason), qPrintable(read.error));
}

void TestTransponders::satnogsDeepNestingIsRefused()
{
    // Nesting far past any real list ends in a refusal, not a crash.
    const int depth = 200000;
    const QByteArray deep = QByteArray(depth, '[') + QByteArray(depth, ']');
    const TransponderImport read = readSatnogsTransmitters(deep, QStringLiteral("deep.json"));
    QVERIFY(!read.ok());
    QVERIFY2(read.error.contains(QStringLiteral("is not JSON")), qPrintable(read.error));

    // A byte-order mark before good JSON is no fault.
    const TransponderImport bom = readSatnogsTransmitters("\xEF\xBB\xBF" + satnogsList({satnogsEntry()}), QStringLiteral("t.json"));
    QVERIFY2(bom.ok(), qPrintable(bom.error));
}

void TestTransponders::skipMessagesAreCapped()
{
    QByteArray many = "[" + satnogsEntry();
    for (int i = 0; i < 1000; ++i)
        many += ",1";
    many += "]";
    const TransponderImport read = readSatnogsTransmitters(many, QStringLiteral("t.json"));
    QVERIFY(read.ok());
    QCOMPARE(read.transponders.size(), 1);
    QCOMPARE(read.skipped.size(), kMostSkipMessages);
    QCOMPARE(read.skippedCount, 1000);
    QCOMPARE(read.skipReport().size(), kMostSkipMessages + 1);
    QCOMPARE(read.skipReport().last(), QStringLiteral("… and 900 more skipped"));
    QVERIFY(read.skipped.last().startsWith(QStringLiteral("t.json: entry 101: ")));
}

// ---- Gpredict ----------------------------------------------------------

void TestTransponders::trspSamplesRead()
{
    const TransponderImport fo29 = readGpredictTrspFile(kData + QStringLiteral("24278.trsp"));
    QVERIFY2(fo29.ok(), qPrintable(fo29.error));
    QCOMPARE(fo29.skipReport(), QStringList());
    QCOMPARE(fo29.transponders.size(), 2);
    const Transponder &linear = fo29.transponders[0];
    QCOMPARE(linear.noradId, 24278);
    QCOMPARE(linear.description, QStringLiteral("Mode V/U linear"));
    QCOMPARE(linear.uplinkLowHz.value(), 145900000.0);
    QCOMPARE(linear.uplinkHighHz.value(), 146000000.0);
    QCOMPARE(linear.downlinkLowHz.value(), 435800000.0);
    QCOMPARE(linear.downlinkHighHz.value(), 435900000.0);
    QVERIFY(linear.inverting);
    QVERIFY(linear.alive); // a .trsp file says nothing of it
    QCOMPARE(linear.mode, QStringLiteral("SSB/CW"));
    QVERIFY(linear.uuid.isEmpty());
    const Transponder &cw = fo29.transponders[1];
    QCOMPARE(cw.description, QStringLiteral("CW beacon"));
    QVERIFY(!cw.hasUplink());
    QVERIFY(!cw.isLinear());
    QVERIFY(!cw.inverting);

    // Spaces around '=', an escape in a value, keys not read, 0 as none.
    const TransponderImport iss = readGpredictTrspFile(kData + QStringLiteral("25544.trsp"));
    QVERIFY2(iss.ok(), qPrintable(iss.error));
    QCOMPARE(iss.skipReport(), QStringList());
    QCOMPARE(iss.transponders.size(), 3);
    QCOMPARE(iss.transponders[0].uplinkLowHz.value(), 145990000.0);
    QCOMPARE(iss.transponders[0].downlinkLowHz.value(), 437800000.0);
    QCOMPARE(iss.transponders[1].mode, QStringLiteral("AFSK 1200 bps"));
    QVERIFY(!iss.transponders[2].hasUplink());

    // CRLF line ends, INVERT=1, a file name with leading zeros.
    const TransponderImport ao7 = readGpredictTrspFile(kData + QStringLiteral("07530.trsp"));
    QVERIFY2(ao7.ok(), qPrintable(ao7.error));
    QCOMPARE(ao7.transponders.size(), 2);
    QCOMPARE(ao7.transponders[0].noradId, 7530);
    QCOMPARE(ao7.transponders[0].mode, QStringLiteral("SSB"));
    QVERIFY(!ao7.transponders[0].inverting);
    QVERIFY(ao7.transponders[1].inverting);
    QCOMPARE(ao7.transponders[1].uplinkForDownlink(145.950e6).value(), 432.150e6);
}

void TestTransponders::trspNoradIdFromFileName_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<int>("norad");
    QTest::newRow("plain") << "25544.trsp" << 25544;
    QTest::newRow("in a folder") << "/home/op/.config/Gpredict/trsp/24278.trsp" << 24278;
    QTest::newRow("leading zeros") << "07530.trsp" << 7530;
    QTest::newRow("nine digits") << "999999999.trsp" << 999999999;
    QTest::newRow("ten digits") << "1234567890.trsp" << 0;
    QTest::newRow("zero") << "0.trsp" << 0;
    QTest::newRow("a name") << "fo29.trsp" << 0;
    QTest::newRow("another suffix") << "25544.txt" << 0;
    QTest::newRow("a sign") << "-25544.trsp" << 0;
    QTest::newRow("no name") << ".trsp" << 0;
}

void TestTransponders::trspNoradIdFromFileName()
{
    QFETCH(QString, path);
    QFETCH(int, norad);
    QCOMPARE(noradIdFromTrspFileName(path).value_or(0), norad);
}

void TestTransponders::trspBadGroupsAreSkippedNamingTheField_data()
{
    QTest::addColumn<QByteArray>("group");
    QTest::addColumn<QString>("message");
    // The group starts on line 3, after a good one on lines 1-2.
    const auto row = [](const char *tag, const QByteArray &group, const char *message) {
        QTest::newRow(tag) << group << QString::fromUtf8(message);
    };
    row("not a number", "[Mode V]\nDOWN_LOW=abc\n", "line 4 [Mode V]: DOWN_LOW 'abc' is not a number");
    row("nan", "[Mode V]\nDOWN_LOW=nan\n", "line 4 [Mode V]: DOWN_LOW 'nan' is not a finite number");
    row("inf", "[Mode V]\nUP_LOW=inf\nDOWN_LOW=145800000\n", "line 4 [Mode V]: UP_LOW 'inf' is not a finite number");
    row("1e999", "[Mode V]\nDOWN_HIGH=1e999\nDOWN_LOW=145800000\n",
        "line 4 [Mode V]: DOWN_HIGH '1e999' is not a");
    row("negative", "[Mode V]\nDOWN_LOW=-145800000\n", "line 4 [Mode V]: DOWN_LOW -145800000 Hz is negative");
    row("above 300 GHz", "[Mode V]\nDOWN_LOW=3e11\nDOWN_HIGH=300000000001\n",
        "line 5 [Mode V]: DOWN_HIGH 300000000001 Hz is above 300 GHz");
    row("low above high", "[Mode V]\nUP_LOW=146000000\nUP_HIGH=145900000\nDOWN_LOW=435800000\n",
        "line 3 [Mode V]: UP_LOW 146000000 Hz is above UP_HIGH 145900000 Hz");
    row("no frequency", "[Mode V]\nMODE=FM\n", "line 3 [Mode V]: no uplink or downlink frequency");
    row("only zeros", "[Mode V]\nUP_LOW=0\nDOWN_LOW=0\n", "line 3 [Mode V]: no uplink or downlink frequency");
    row("invert unreadable", "[Mode V]\nDOWN_LOW=145800000\nINVERT=yes\n",
        "line 5 [Mode V]: INVERT 'yes' is not true or false");
    row("invert in capitals", "[Mode V]\nDOWN_LOW=145800000\nINVERT=TRUE\n",
        "line 5 [Mode V]: INVERT 'TRUE' is not true or false");
    row("header not closed", "[Mode V\nDOWN_LOW=145800000\n", "line 3: '[Mode V' is not a [transponder name] header");
    row("header empty", "[]\nDOWN_LOW=145800000\n", "line 3: '[]' is not a [transponder name] header");
    row("header with a bracket", "[Mode [V]]\nDOWN_LOW=145800000\n",
        "line 3: '[Mode [V]]' is not a [transponder name] header");
    row("a stray line", "DOWN_LOW 145800000\n",
        "line 3: 'DOWN_LOW 145800000' is neither a [group], a KEY=value line nor a # comment");
    row("no key", "=145800000\n", "line 3: '=145800000' is neither a [group]");
    row("escaped value", "[Mode V]\nDOWN_LOW=x\x1b[2J\n", "line 4 [Mode V]: DOWN_LOW 'x\\x1b[2J' is not a number");
    row("escaped header", "[Mode \x1b]\nDOWN_LOW=1\n", "line 3: '[Mode \\x1b]' is not a [transponder name] header");
}

void TestTransponders::trspBadGroupsAreSkippedNamingTheField()
{
    QFETCH(QByteArray, group);
    QFETCH(QString, message);
    const QByteArray text = "[Good]\nDOWN_LOW=145800000\n" + group;
    const TransponderImport read = readGpredictTrsp(text, QStringLiteral("25544.trsp"), 25544);
    QVERIFY2(read.ok(), qPrintable(read.error));
    QCOMPARE(read.transponders.size(), 1);
    QCOMPARE(read.transponders[0].description, QStringLiteral("Good"));
    QCOMPARE(read.skippedCount, 1);
    QVERIFY2(firstSkip(read).startsWith(QStringLiteral("25544.trsp: ") + message), qPrintable(firstSkip(read)));
}

void TestTransponders::trspFileKeepsTheGoodGroups()
{
    const QString path = kData + QStringLiteral("44909-bad.trsp");
    // Not named after a number: refused unless the number is given.
    const TransponderImport unnamed = readGpredictTrspFile(path);
    QVERIFY(!unnamed.ok());
    QVERIFY2(unnamed.error.contains(QStringLiteral("cannot tell which satellite")), qPrintable(unnamed.error));

    const TransponderImport read = readGpredictTrspFile(path, 44909);
    QVERIFY2(read.ok(), qPrintable(read.error));
    QCOMPARE(read.transponders.size(), 1);
    QCOMPARE(read.transponders[0].noradId, 44909);
    QCOMPARE(read.transponders[0].description, QStringLiteral("Linear transponder"));
    const QStringList expected{
        path + QStringLiteral(": line 11 [Beacon]: DOWN_LOW 'nan' is not a finite number"),
        path + QStringLiteral(": line 13 [Upside down]: DOWN_LOW 435670000 Hz is above DOWN_HIGH 435610000 Hz"),
        path + QStringLiteral(": line 22 [Sense unknown]: INVERT 'yes' is not true or false"),
        path + QStringLiteral(": line 24: '[Telemetry' is not a [transponder name] header"),
    };
    QCOMPARE(read.skipped, expected);
}

void TestTransponders::trspGroupsMergeAndLastKeyWins()
{
    // As the key-file format has it: a group named twice is one group, a
    // key given twice keeps its last value; comments may be indented.
    const QByteArray text = "  # a comment\n[Mode V]\nDOWN_LOW=145800000\nMODE=AM\n[Other]\nDOWN_LOW=1000000\n"
                            "[Mode V]\nMODE=FM\n  DOWN_LOW = 145900000  \n";
    const TransponderImport read = readGpredictTrsp(text, QStringLiteral("t.trsp"), 25544);
    QVERIFY2(read.ok(), qPrintable(read.error));
    QCOMPARE(read.skipReport(), QStringList());
    QCOMPARE(read.transponders.size(), 2);
    QCOMPARE(read.transponders[0].description, QStringLiteral("Mode V"));
    QCOMPARE(read.transponders[0].mode, QStringLiteral("FM"));
    QCOMPARE(read.transponders[0].downlinkLowHz.value(), 145900000.0);
    QCOMPARE(read.transponders[1].description, QStringLiteral("Other"));

    // A key before any group is skipped, the rest kept.
    const TransponderImport early = readGpredictTrsp("DOWN_LOW=1\n[A]\nDOWN_LOW=2\n", QStringLiteral("t.trsp"), 1);
    QCOMPARE(early.transponders.size(), 1);
    QCOMPARE(early.skipped, QStringList{QStringLiteral("t.trsp: line 1: 'DOWN_LOW=1' comes before any [transponder name] header")});
}

void TestTransponders::trspWholeSourceRefusals_data()
{
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<int>("norad");
    QTest::addColumn<QString>("reason");
    QTest::newRow("empty") << QByteArray() << 25544 << "no transponder groups in it";
    QTest::newRow("comments only") << QByteArray("# nothing\n\n") << 25544 << "no transponder groups in it";
    QTest::newRow("all bad") << QByteArray("[A]\nDOWN_LOW=nan\n[B]\nMODE=FM\n") << 25544
                             << "no usable transponder: all 2 transponder groups were skipped";
    QTest::newRow("not UTF-8") << QByteArray("[A]\nDOWN_LOW=145800000\nMODE=\xc3\x28\n") << 25544 << "is not UTF-8 text";
    QTest::newRow("binary") << QByteArray("\x7f" "ELF\x02\x01\x01\x00\x00\xff\xfe", 11) << 25544 << "is not UTF-8 text";
    QTest::newRow("no satellite") << QByteArray("[A]\nDOWN_LOW=145800000\n") << 0 << "0 is not a catalogue number";
}

void TestTransponders::trspWholeSourceRefusals()
{
    QFETCH(QByteArray, bytes);
    QFETCH(int, norad);
    QFETCH(QString, reason);
    const TransponderImport read = readGpredictTrsp(bytes, QStringLiteral("25544.trsp"), norad);
    QVERIFY(!read.ok());
    QVERIFY(read.transponders.isEmpty());
    QVERIFY2(read.error.startsWith(QStringLiteral("25544.trsp: ")), qPrintable(read.error));
    QVERIFY2(read.error.contains(reason), qPrintable(read.error));
}

// ---- Files -------------------------------------------------------------

void TestTransponders::filesThatAreNotFilesAreRefused()
{
    const TransponderImport device = readSatnogsTransmittersFile(QStringLiteral("/dev/zero"));
    QVERIFY(!device.ok());
    QVERIFY2(device.error.contains(QStringLiteral("character device")), qPrintable(device.error));

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString folder = dir.filePath(QStringLiteral("25544.trsp"));
    QVERIFY(QDir().mkdir(folder));
    const TransponderImport directory = readGpredictTrspFile(folder);
    QVERIFY(!directory.ok());
    QVERIFY2(directory.error.contains(QStringLiteral("a directory")), qPrintable(directory.error));

    const TransponderImport missing = readGpredictTrspFile(dir.filePath(QStringLiteral("7530.trsp")));
    QVERIFY(!missing.ok());
    QVERIFY2(missing.error.contains(QStringLiteral("7530.trsp")), qPrintable(missing.error));
}

void TestTransponders::filesOverTheCapAreRefused()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const auto fileOf = [&](const QString &name, qint64 size) {
        const QString path = dir.filePath(name);
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly) || !file.resize(size))
            return QString();
        return path;
    };
    const QString list = fileOf(QStringLiteral("transmitters.json"), kLargestTransmitterList + 1);
    QVERIFY(!list.isEmpty());
    const TransponderImport bigList = readSatnogsTransmittersFile(list);
    QVERIFY(!bigList.ok());
    QVERIFY2(bigList.error.contains(QStringLiteral("over the 16 MiB limit")), qPrintable(bigList.error));

    const QString trsp = fileOf(QStringLiteral("25544.trsp"), kLargestTrspFile + 1);
    QVERIFY(!trsp.isEmpty());
    const TransponderImport bigTrsp = readGpredictTrspFile(trsp);
    QVERIFY(!bigTrsp.ok());
    QVERIFY2(bigTrsp.error.contains(QStringLiteral("over the 1 MiB limit")), qPrintable(bigTrsp.error));
}

void TestTransponders::bothSourcesMergeIntoOneSet()
{
    TransponderSet set;
    const TransponderImport gpredict = readGpredictTrspFile(kData + QStringLiteral("24278.trsp"));
    const TransponderImport satnogs = readSatnogsTransmittersFile(kData + QStringLiteral("satnogs-transmitters.json"));
    QVERIFY(gpredict.ok() && satnogs.ok());
    QCOMPARE(set.merge(gpredict.transponders), 0);
    // SatNOGS DB's FO-29 beacon repeats the Gpredict file's one (same
    // frequency and mode); its linear has another mode name (SSB, not
    // SSB/CW), so both stay.
    QCOMPARE(set.merge(satnogs.transponders), 1);
    const QList<Transponder> fo29 = set.forSatellite(24278);
    QCOMPARE(fo29.size(), 3);
    QCOMPARE(fo29[0].description, QStringLiteral("Mode V/U linear"));
    QCOMPARE(fo29[1].description, QStringLiteral("CW beacon"));
    QCOMPARE(fo29[2].uuid, QStringLiteral("SlwSample0000000000004"));
    QCOMPARE(set.defaultFor(24278)->mode, QStringLiteral("SSB/CW"));
}

QTEST_GUILESS_MAIN(TestTransponders)
#include "tst_transponders.moc"
