// SPDX-License-Identifier: GPL-3.0-or-later
// Reading element sets: the fields, the checksum, two- and three-line files,
// refusals that name the line and the reason while the rest still loads,
// and finding a set by number or name.

#include "sky/tleformat.h"
#include "sky/elementsetformat.h"
#include "sky/satellitenames.h"

#include <QTest>

using namespace slew::sky;

namespace {

const QString kIssName = QStringLiteral("ISS (ZARYA)");
// Real sets: the ISS (epoch 2008-09-20) as Wikipedia's TLE article prints
// it, and NOAA 19 from the test data snapshot.
const QString kIss1 = QStringLiteral("1 25544U 98067A   08264.51782528 -.00002182  00000-0 -11606-4 0  2927");
const QString kIss2 = QStringLiteral("2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.72125391563537");
const QString kNoaa1 = QStringLiteral("1 33591U 09005A   18020.91958580  .00000107  00000-0  83477-4 0  9992");
const QString kNoaa2 = QStringLiteral("2 33591  99.1238 356.1693 0014450  24.0615 336.1228 14.12247534461122");

// Change one column (1-based) and fix the checksum, so only the field is wrong.
QString withColumn(QString line, int column, QChar c)
{
    line[column - 1] = c;
    line[68] = QChar(u'0' + tleChecksum(line));
    return line;
}

// Replace columns first..last (1-based) with `text`, right-aligned, and fix
// the checksum: the set is well-formed but for that field.
QString withField(QString line, int first, int last, const QString &text)
{
    const int width = last - first + 1;
    line.replace(first - 1, width, text.rightJustified(width, u' ', true));
    line[68] = QChar(u'0' + tleChecksum(line));
    return line;
}

} // namespace

class TestTle : public QObject {
    Q_OBJECT
private slots:
    void readsTheFields();
    void satellitesAreFoundByTheNamesOperatorsUse_data();
    void satellitesAreFoundByTheNamesOperatorsUse();
    void amsatNamesFindSetsThatLackThem();
    void theNameTableSaysWhereALineIsWrong();
    void checksum_data();
    void checksum();
    void refusals_data();
    void refusals();
    void fileKeepsLoadingPastBadSets();
    void findsByNumberAndName_data();
    void findsByNumberAndName();
    void notANumberIsRefusedInEveryField_data();
    void notANumberIsRefusedInEveryField();
    void duplicatesKeepTheNewestEpoch();
    void ambiguousNamesAreRefusedNamingTheMatches();
    void filesThatAreNotFilesAreRefused();
    void fileCutAfterALine1NamesALineOfIt();
};

void TestTle::fileCutAfterALine1NamesALineOfIt()
{
    // Found by fuzz_tle: a download cut after a line 1 was refused at a
    // line past the end of the file.
    const ElementSetRead read = readTleText(kIssName + u'\n' + kIss1);
    QCOMPARE(read.refusals.size(), 1);
    QCOMPARE(read.refusals[0].line, 2);
}

void TestTle::notANumberIsRefusedInEveryField_data()
{
    QTest::addColumn<QString>("line1");
    QTest::addColumn<QString>("line2");
    QTest::addColumn<QString>("reasonContains");
    for (const QString &bad : {QStringLiteral("nan"), QStringLiteral("-nan"), QStringLiteral("inf"), QStringLiteral("-inf")}) {
        const QByteArray tag = bad.toLatin1();
        QTest::newRow(tag + " mean motion") << kIss1 << withField(kIss2, 53, 63, bad) << "mean motion";
        QTest::newRow(tag + " inclination") << kIss1 << withField(kIss2, 9, 16, bad) << "inclination";
        QTest::newRow(tag + " node") << kIss1 << withField(kIss2, 18, 25, bad) << "right ascension";
        QTest::newRow(tag + " perigee") << kIss1 << withField(kIss2, 35, 42, bad) << "perigee";
        QTest::newRow(tag + " anomaly") << kIss1 << withField(kIss2, 44, 51, bad) << "anomaly";
        QTest::newRow(tag + " epoch") << withField(kIss1, 21, 32, bad) << kIss2 << "epoch";
        QTest::newRow(tag + " mean motion dot") << withField(kIss1, 34, 43, bad) << kIss2 << "first derivative";
    }
    QTest::newRow("overflow to infinity") << kIss1 << withField(kIss2, 53, 63, QStringLiteral("1e999")) << "mean motion";
    QTest::newRow("no orbit that fast") << kIss1 << withField(kIss2, 53, 63, QStringLiteral("99.0")) << "0..20 rev/day";
}

void TestTle::notANumberIsRefusedInEveryField()
{
    // Qt reads "nan" and "inf" as numbers, and a NaN passes every range
    // check; a set carrying one made the pass search spin for ever.
    QFETCH(QString, line1);
    QFETCH(QString, line2);
    QFETCH(QString, reasonContains);
    ElementSet t;
    ElementSetRefusal r;
    QVERIFY2(!parseTle(line1, line2, &t, &r), "a set with a field that is not a finite number must be refused");
    QVERIFY2(r.reason.contains(reasonContains), qPrintable(r.reason));
}

void TestTle::duplicatesKeepTheNewestEpoch()
{
    // Two group files put together: the ISS twice, the second copy newer.
    const QString newer1 = withField(kIss1, 21, 32, QStringLiteral("265.51782528"));
    const QString text = QStringList{kIssName, kIss1, kIss2, kNoaa1, kNoaa2, QStringLiteral("ISS (NEWER)"), newer1, kIss2}
                             .join(u'\n');
    const QList<ElementSet> merged = mergeByCatalogueNumber(readTleText(text).sets);
    QCOMPARE(merged.size(), 2);
    QCOMPARE(merged[0].catalogueNumber, 25544);
    QCOMPARE(merged[0].epochJulianDay, 2454730.5);
    QCOMPARE(merged[0].epochDayFraction, 0.51782528);
    QCOMPARE(merged[0].name, QStringLiteral("ISS (NEWER)"));
    QCOMPARE(merged[1].catalogueNumber, 33591);
    QString error;
    QVERIFY2(findOneSatellite(merged, QStringLiteral("25544"), &error), qPrintable(error));
}

void TestTle::ambiguousNamesAreRefusedNamingTheMatches()
{
    QList<ElementSet> sets(3);
    sets[0].name = QStringLiteral("NOAA 15");
    sets[0].catalogueNumber = 25338;
    sets[1].name = QStringLiteral("NOAA 16 [-]");
    sets[1].catalogueNumber = 26536;
    sets[2].name = QStringLiteral("NOAA 19");
    sets[2].catalogueNumber = 33591;
    QString error;
    QVERIFY(!findOneSatellite(sets, QStringLiteral("NOAA"), &error));
    QVERIFY2(error.startsWith(QStringLiteral("'NOAA' matches 3 satellites: NOAA 15 (25338), NOAA 16 [-] (26536), NOAA 19 (33591)")),
             qPrintable(error));
    QVERIFY(!findOneSatellite(sets, QStringLiteral("GOES"), &error));
    QCOMPARE(error, QStringLiteral("no satellite 'GOES'"));
    QVERIFY(!findOneSatellite(sets, QString::fromLatin1("\x1b[2J"), &error));
    QVERIFY2(!error.contains(QChar(0x1b)), qPrintable(error));
    const ElementSet *one = findOneSatellite(sets, QStringLiteral("noaa 19"), &error);
    QVERIFY(one);
    QCOMPARE(one->catalogueNumber, 33591);
}

void TestTle::satellitesAreFoundByTheNamesOperatorsUse_data()
{
    QTest::addColumn<QString>("query");
    QTest::addColumn<int>("catalogueNumber");
    // Gpredict's 2018 sets: "FOX-1B (AO-91)", "ISS (ZARYA)", "JAS-2 (FO-29)".
    QTest::newRow("AO-91") << "AO-91" << 43017;
    QTest::newRow("ao 91") << "ao 91" << 43017;
    QTest::newRow("SO-50") << "SO-50" << 27607;
    QTest::newRow("FO-29") << "FO-29" << 24278;
    QTest::newRow("JAS-2") << "JAS-2" << 24278;
    QTest::newRow("ZARYA") << "ZARYA" << 25544;
    QTest::newRow("ISS") << "ISS" << 25544;
    QTest::newRow("AO-7, not AO-71 or AO-73") << "AO-7" << 7530;
    QTest::newRow("OSCAR 7") << "OSCAR 7" << 7530;
    QTest::newRow("OSCAR7, its space eaten") << "OSCAR7" << 7530;
    QTest::newRow("part of a name") << "ZARY" << 25544;
    QTest::newRow("catalogue number") << "43017" << 43017;
}

void TestTle::satellitesAreFoundByTheNamesOperatorsUse()
{
    QFETCH(QString, query);
    QFETCH(int, catalogueNumber);
    static const ElementSetFile gpredict =
        readElementSetFile(QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle"));
    QVERIFY2(gpredict.sets.size() > 900, qPrintable(gpredict.error));
    QString error;
    const ElementSet *found = findOneSatellite(gpredict.sets, query, &error);
    QVERIFY2(found, qPrintable(error));
    QCOMPARE(found->catalogueNumber, catalogueNumber);
}

void TestTle::amsatNamesFindSetsThatLackThem()
{
    // A set named as its operator names it, without the AMSAT designation:
    // found by the built-in table, and by its own name as before.
    QList<ElementSet> sets(2);
    sets[0].name = QStringLiteral("RADFXSAT");
    sets[0].catalogueNumber = 43017;
    sets[1].name = QStringLiteral("ES'HAIL 2");
    sets[1].catalogueNumber = 43700;
    QString error;
    for (const auto &[query, number] : {std::pair{"AO-91", 43017}, std::pair{"FOX-1B", 43017}, std::pair{"QO-100", 43700},
                                         std::pair{"RADFX", 43017}}) {
        const ElementSet *found = findOneSatellite(sets, QString::fromLatin1(query), &error);
        QVERIFY2(found, qPrintable(error));
        QCOMPARE(found->catalogueNumber, number);
    }
    QVERIFY(!findOneSatellite(sets, QStringLiteral("SO-50"), &error)); // in the table, not in these sets
    QCOMPARE(error, QStringLiteral("no satellite 'SO-50'"));
    QVERIFY(!findOneSatellite(sets, QStringLiteral(" - "), &error)); // nothing to search by
}

void TestTle::theNameTableSaysWhereALineIsWrong()
{
    // The built-in table reads whole.
    SatelliteNameTable table;
    QStringList problems;
    table.read(builtInSatelliteNames(), QStringLiteral("satellite-names.txt"), &problems);
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join(u'\n')));
    QCOMPARE(table.size(), 33);
    QCOMPARE(table.catalogueNumber(satelliteNameKey(u"JAS-2")), 24278);
    QCOMPARE(table.catalogueNumber(satelliteNameKey(u"es'hail 2")), 43700);

    // An operator's file after it: its good lines kept, a name it gives
    // another satellite its own, each bad line said with its place.
    table.read(u"# mine\n"
               u"99999 MY CUBESAT   # the club's\n"
               u"ISS 25544\n"
               u"12x4 AO-1\n"
               u"42\n"
               u"1234567890 TOO LONG\n"
               u"0 ZERO\n"
               u"\t 25338   jas-2 \r\n",
               QStringLiteral("/home/op/.config/Slew/satellite-names.txt"), &problems);
    QCOMPARE(problems,
             QStringList({QStringLiteral("/home/op/.config/Slew/satellite-names.txt:3: 'ISS' is not a catalogue number; "
                                         "a line is a number and a name"),
                          QStringLiteral("/home/op/.config/Slew/satellite-names.txt:4: '12x4' is not a catalogue number; "
                                         "a line is a number and a name"),
                          QStringLiteral("/home/op/.config/Slew/satellite-names.txt:5: no name after the catalogue number 42"),
                          QStringLiteral("/home/op/.config/Slew/satellite-names.txt:6: '1234567890' is not a catalogue "
                                         "number; a line is a number and a name"),
                          QStringLiteral("/home/op/.config/Slew/satellite-names.txt:7: '0' is not a catalogue number; "
                                         "a line is a number and a name")}));
    QCOMPARE(table.catalogueNumber(QStringLiteral("MYCUBESAT")), 99999);
    QCOMPARE(table.catalogueNumber(QStringLiteral("JAS2")), 25338);
    QCOMPARE(table.catalogueNumber(QStringLiteral("FO29")), 24278); // the rest stays
    QCOMPARE(table.size(), 34);
    QCOMPARE(table.catalogueNumber(QStringLiteral("ISS25544")), std::nullopt);
}

void TestTle::filesThatAreNotFilesAreRefused()
{
    const ElementSetFile zero = readElementSetFile(QStringLiteral("/dev/zero"));
    QVERIFY(zero.sets.isEmpty());
    QVERIFY2(zero.error.contains(QStringLiteral("character device")), qPrintable(zero.error));
}

void TestTle::readsTheFields()
{
    ElementSet t;
    ElementSetRefusal r;
    QVERIFY2(parseTle(kIss1, kIss2, &t, &r), qPrintable(r.reason));
    QCOMPARE(t.catalogueNumber, 25544);
    QCOMPARE(t.designator, QStringLiteral("1998-067A")); // as OMM writes it
    QCOMPARE(t.classification, 'U');
    QCOMPARE(t.elementSetNumber, 292);
    // The day's fraction is the double nearest to the eight decimals printed.
    QCOMPARE(t.epochDayFraction, 0.51782528);
    QCOMPARE(t.meanMotionDot, -0.00002182);
    QCOMPARE(t.meanMotionDdot, 0.0);
    QCOMPARE(t.bstar, -1.1606e-5); // the double nearest, as an OMM's "-1.1606E-5" reads
    QCOMPARE(t.inclinationDeg, 51.6416);
    QCOMPARE(t.raanDeg, 247.4627);
    QCOMPARE(t.eccentricity, 0.0006703);
    QCOMPARE(t.argPerigeeDeg, 130.5360);
    QCOMPARE(t.meanAnomalyDeg, 325.0288);
    QCOMPARE(t.meanMotionRevPerDay, 15.72125391);
    QCOMPARE(t.revolutionNumber, 56353);
    // 2008 day 264.5178 is 20 September 12:25:40 UTC: JD 2454730.0178.
    QCOMPARE(t.epochJulianDay, 2454729.5);
    QVERIFY(std::fabs(t.epochJulian() - 2454730.01782528) < 1e-9);
}

void TestTle::checksum_data()
{
    QTest::addColumn<QString>("line");
    QTest::addColumn<int>("sum");
    QTest::newRow("ISS line 1") << kIss1 << 7;
    QTest::newRow("ISS line 2") << kIss2 << 7;
    QTest::newRow("minus counts one") << QStringLiteral("1 -") << 2;
    QTest::newRow("letters and plus count nothing") << QStringLiteral("ABC+.") << 0;
}

void TestTle::checksum()
{
    QFETCH(QString, line);
    QFETCH(int, sum);
    QCOMPARE(tleChecksum(line), sum);
}

void TestTle::refusals_data()
{
    QTest::addColumn<QString>("line1");
    QTest::addColumn<QString>("line2");
    QTest::addColumn<int>("line");
    QTest::addColumn<QString>("reasonContains");
    QString badSum1 = kIss1;
    badSum1[68] = u'8';
    QString badSum2 = kIss2;
    badSum2[68] = u'0';
    QTest::newRow("checksum line 1") << badSum1 << kIss2 << 1 << QStringLiteral("checksum");
    QTest::newRow("checksum line 2") << kIss1 << badSum2 << 2 << QStringLiteral("checksum");
    QTest::newRow("short line") << kIss1.left(40) << kIss2 << 1 << QStringLiteral("69 columns");
    QTest::newRow("lines swapped") << kIss2 << kIss1 << 1 << QStringLiteral("line 1");
    QTest::newRow("numbers differ") << kIss1 << kNoaa2 << 2 << QStringLiteral("catalogue number");
    QTest::newRow("inclination over 180") << kIss1 << withColumn(kIss2, 9, u'2') << 2 << QStringLiteral("inclination");
    QTest::newRow("eccentricity not digits")
        << kIss1 << withColumn(kIss2, 28, u'x') << 2 << QStringLiteral("eccentricity");
    QTest::newRow("epoch day zero") << withColumn(withColumn(withColumn(kIss1, 21, u'0'), 22, u'0'), 23, u'0') << kIss2
                                    << 1 << QStringLiteral("epoch day");
    QTest::newRow("bad B*") << withColumn(kIss1, 60, u'x') << kIss2 << 1 << QStringLiteral("B*");
}

void TestTle::refusals()
{
    QFETCH(QString, line1);
    QFETCH(QString, line2);
    QFETCH(int, line);
    QFETCH(QString, reasonContains);
    ElementSet t;
    ElementSetRefusal r;
    QVERIFY(!parseTle(line1, line2, &t, &r));
    QCOMPARE(r.line, line);
    QVERIFY2(r.reason.contains(reasonContains), qPrintable(r.reason));
}

void TestTle::fileKeepsLoadingPastBadSets()
{
    QString badSum = kIss2;
    badSum[68] = u'0';
    const QString text = QStringList{
        kIssName, kIss1, kIss2,                   // 1-3: three-line set
        QString(), QStringLiteral("# comment"),   // 4-5
        kNoaa1, kNoaa2,                           // 6-7: two-line set
        QStringLiteral("BROKEN"), kIss1, badSum,  // 8-10: bad checksum on line 10
        kIss2,                                    // 11: line 2 without line 1
        QStringLiteral("0 NOAA 19"), kNoaa1, kNoaa2, // 12-14: CelesTrak's "0 " name prefix
        QStringLiteral("LONELY NAME"),            // 15
    }.join(u'\n');
    const ElementSetRead result = readTleText(text);
    QCOMPARE(result.sets.size(), 3);
    QCOMPARE(result.sets[0].name, kIssName);
    QCOMPARE(result.sets[1].name, QString());
    QCOMPARE(result.sets[1].displayName(), QStringLiteral("33591"));
    QCOMPARE(result.sets[2].name, QStringLiteral("NOAA 19"));
    QCOMPARE(result.refusals.size(), 3);
    QCOMPARE(result.refusals[0].line, 10);
    QVERIFY(result.refusals[0].reason.contains(QStringLiteral("checksum")));
    QCOMPARE(result.refusals[1].line, 11);
    QCOMPARE(result.refusals[2].line, 15);
}

void TestTle::findsByNumberAndName_data()
{
    QTest::addColumn<QString>("query");
    QTest::addColumn<QList<int>>("numbers");
    QTest::newRow("number") << QStringLiteral("33591") << QList<int>{33591};
    QTest::newRow("exact name, any case") << QStringLiteral("iss (zarya)") << QList<int>{25544};
    QTest::newRow("prefix") << QStringLiteral("noaa") << QList<int>{33591, 28654};
    QTest::newRow("exact beats prefix") << QStringLiteral("NOAA 18") << QList<int>{28654};
    QTest::newRow("nothing") << QStringLiteral("GOES") << QList<int>{};
}

void TestTle::findsByNumberAndName()
{
    QFETCH(QString, query);
    QFETCH(QList<int>, numbers);
    QList<ElementSet> sets(3);
    sets[0].name = kIssName;
    sets[0].catalogueNumber = 25544;
    sets[1].name = QStringLiteral("NOAA 19");
    sets[1].catalogueNumber = 33591;
    sets[2].name = QStringLiteral("NOAA 18");
    sets[2].catalogueNumber = 28654;
    QList<int> found;
    for (const ElementSet *t : findSatellites(sets, query))
        found.append(t->catalogueNumber);
    QCOMPARE(found, numbers);
}

QTEST_GUILESS_MAIN(TestTle)
#include "tst_tle.moc"
