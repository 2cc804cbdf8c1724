// SPDX-License-Identifier: GPL-3.0-or-later
// The GP forms of element sets (CSV, OMM XML, JSON, OMM KVN) beside the
// TLE: each read from the files of tests/data/gp, told apart by content,
// identical to the same set read as a TLE (states bit for bit), written
// back and read again unchanged; the epoch to the nanosecond; Alpha-5; and
// bad input refused with the file's line (or entry), the keyword and why,
// while the rest still loads.

#include "sky/elementsetformat.h"
#include "sky/gpcsv.h"
#include "sky/gpfields.h"
#include "sky/gpjson.h"
#include "sky/ommkvn.h"
#include "sky/ommxml.h"
#include "sky/sgp4.h"
#include "sky/tleformat.h"
#include "sky/utctime.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <sys/stat.h>

using namespace slew::sky;

namespace {

const QString kData = QStringLiteral(SLEW_TEST_DATA_DIR "/gp/");
const QList<int> kNumbers = {24278, 125544, 270033591, 115429, 236411};

QByteArray fileBytes(const QString &name)
{
    QFile f(kData + name);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

QList<int> numbersOf(const QList<ElementSet> &sets)
{
    QList<int> numbers;
    for (const ElementSet &s : sets)
        numbers << s.catalogueNumber;
    return numbers;
}

// Every field the readers fill, compared exactly: the forms carry the same
// decimals, so they must give the same doubles.
bool sameSet(const ElementSet &a, const ElementSet &b, QString *why)
{
    const struct {
        const char *name;
        double x, y;
    } fields[] = {{"epochJulianDay", a.epochJulianDay, b.epochJulianDay},
                  {"epochDayFraction", a.epochDayFraction, b.epochDayFraction},
                  {"meanMotion", a.meanMotionRevPerDay, b.meanMotionRevPerDay},
                  {"eccentricity", a.eccentricity, b.eccentricity},
                  {"inclination", a.inclinationDeg, b.inclinationDeg},
                  {"raan", a.raanDeg, b.raanDeg},
                  {"argPerigee", a.argPerigeeDeg, b.argPerigeeDeg},
                  {"meanAnomaly", a.meanAnomalyDeg, b.meanAnomalyDeg},
                  {"bstar", a.bstar, b.bstar},
                  {"meanMotionDot", a.meanMotionDot, b.meanMotionDot},
                  {"meanMotionDdot", a.meanMotionDdot, b.meanMotionDdot},
                  {"catalogueNumber", double(a.catalogueNumber), double(b.catalogueNumber)},
                  {"revolutionNumber", double(a.revolutionNumber), double(b.revolutionNumber)},
                  {"elementSetNumber", double(a.elementSetNumber), double(b.elementSetNumber)}};
    for (const auto &f : fields) {
        if (f.x != f.y) {
            *why = QStringLiteral("%1: %2 against %3").arg(QLatin1String(f.name)).arg(f.x, 0, 'g', 17).arg(f.y, 0, 'g', 17);
            return false;
        }
    }
    if (a.name != b.name || a.designator != b.designator) {
        *why = QStringLiteral("%1 / %2 against %3 / %4").arg(a.name, a.designator, b.name, b.designator);
        return false;
    }
    return true;
}

const QByteArray kCsvHeader = "OBJECT_NAME,OBJECT_ID,EPOCH,MEAN_MOTION,ECCENTRICITY,INCLINATION,RA_OF_ASC_NODE,"
                              "ARG_OF_PERICENTER,MEAN_ANOMALY,EPHEMERIS_TYPE,CLASSIFICATION_TYPE,NORAD_CAT_ID,"
                              "ELEMENT_SET_NO,REV_AT_EPOCH,BSTAR,MEAN_MOTION_DOT,MEAN_MOTION_DDOT\r\n";
const QByteArray kCsvRow = "NEW SAT,2026-150A,2026-07-11T12:34:56.123456,15.2,.001,97.5,10,20,30,0,U,%1,999,12,"
                           ".00012,.00001,0\r\n";

QByteArray csvRow(int number)
{
    return QByteArray(kCsvRow).replace("%1", QByteArray::number(number));
}

} // namespace

class TestGpForms : public QObject {
    Q_OBJECT
private slots:
    void eachFormReadsTheTestSets_data();
    void eachFormReadsTheTestSets();
    void aTleAndItsOmmGiveIdenticalStates();
    void everyFormWritesWhatItReads_data();
    void everyFormWritesWhatItReads();
    void exportedTlesRoundTripAndNameWhatTheyCannotCarry();
    void alpha5_data();
    void alpha5();
    void epochs_data();
    void epochs();
    void csvByItsHeaderInAnyOrder();
    void badRowsAreRefusedAndTheRestLoads_data();
    void badRowsAreRefusedAndTheRestLoads();
    void xmlWithADoctypeOrEntitiesIsRefusedAtOnce();
    void xmlTooDeepOrBrokenKeepsWhatCameBefore();
    void jsonRefusalsNameTheEntry();
    void kvnUnitsCommentsAndMessagesWithoutVersionLines();
    void otherTheoriesAndFramesAreRefused();
    void devicesAndFifosAreRefused();
    void formsAreToldByContent_data();
    void formsAreToldByContent();
};

void TestGpForms::eachFormReadsTheTestSets_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<ElementSetForm>("form");
    QTest::newRow("CSV") << QStringLiteral("gp-2018.csv") << ElementSetForm::Csv;
    QTest::newRow("OMM XML") << QStringLiteral("gp-2018.xml") << ElementSetForm::OmmXml;
    QTest::newRow("JSON, CelesTrak's numbers") << QStringLiteral("gp-2018.json") << ElementSetForm::Json;
    QTest::newRow("JSON, Space-Track's strings") << QStringLiteral("gp-2018-spacetrack.json") << ElementSetForm::Json;
    QTest::newRow("OMM KVN") << QStringLiteral("gp-2018.kvn") << ElementSetForm::OmmKvn;
}

void TestGpForms::eachFormReadsTheTestSets()
{
    QFETCH(QString, file);
    QFETCH(ElementSetForm, form);
    const ElementSetFile read = readElementSetFile(kData + file);
    QVERIFY2(read.error.isEmpty(), qPrintable(read.error));
    QCOMPARE(read.form, form);
    QVERIFY2(read.refusals.isEmpty(), qPrintable(read.refusals.value(0).reason));
    QCOMPARE(numbersOf(read.sets), kNumbers);
    QCOMPARE(read.sets[2].name, QStringLiteral("GP TEST LEO-9 (NOAA 19 ELEMENTS)"));
    QCOMPARE(read.sets[2].designator, QStringLiteral("2009-005A"));
    // And the same values in every form as in the CSV.
    const ElementSetFile csv = readElementSetFile(kData + QStringLiteral("gp-2018.csv"));
    for (qsizetype i = 0; i < csv.sets.size(); ++i) {
        QString why;
        QVERIFY2(sameSet(read.sets[i], csv.sets[i], &why), qPrintable(why));
    }
}

void TestGpForms::aTleAndItsOmmGiveIdenticalStates()
{
    // The TLE file holds the sets a TLE can carry (Alpha-5 numbers), with
    // the same decimals as the CSV.
    const ElementSetFile tle = readElementSetFile(kData + QStringLiteral("gp-2018.tle"));
    const ElementSetFile csv = readElementSetFile(kData + QStringLiteral("gp-2018.csv"));
    QCOMPARE(tle.form, ElementSetForm::Tle);
    QCOMPARE(numbersOf(tle.sets), (QList<int>{24278, 125544, 115429, 236411}));
    for (const ElementSet &fromTle : tle.sets) {
        const ElementSet *fromCsv = findSatellites(csv.sets, QString::number(fromTle.catalogueNumber)).value(0);
        QVERIFY(fromCsv);
        QString why;
        QVERIFY2(sameSet(fromTle, *fromCsv, &why), qPrintable(why));
        const Sgp4 a(fromTle), b(*fromCsv);
        for (const double minutes : {-1440.0, 0.0, 93.7, 1440.0, 10080.0}) {
            const Sgp4State sa = a.propagate(minutes), sb = b.propagate(minutes);
            QCOMPARE(sa.error, sb.error);
            QCOMPARE(sa.positionKm.x, sb.positionKm.x);
            QCOMPARE(sa.positionKm.y, sb.positionKm.y);
            QCOMPARE(sa.positionKm.z, sb.positionKm.z);
            QCOMPARE(sa.velocityKmS.x, sb.velocityKmS.x);
        }
    }
}

void TestGpForms::everyFormWritesWhatItReads_data()
{
    QTest::addColumn<ElementSetForm>("form");
    QTest::newRow("CSV") << ElementSetForm::Csv;
    QTest::newRow("OMM XML") << ElementSetForm::OmmXml;
    QTest::newRow("JSON") << ElementSetForm::Json;
    QTest::newRow("OMM KVN") << ElementSetForm::OmmKvn;
}

void TestGpForms::everyFormWritesWhatItReads()
{
    QFETCH(ElementSetForm, form);
    QList<ElementSet> sets = readElementSetFile(kData + QStringLiteral("gp-2018.csv")).sets;
    // An epoch with nanoseconds, and a name that needs quoting or escaping.
    sets[0].name = QStringLiteral("A, \"QUOTED\" <NAME> & [-]");
    sets[0].epochDayFraction = double(12345678901234LL) / 86400e9;
    const WrittenElementSets written = writeElementSets(sets, form, utcFromJulian(*julianFromIso(QStringLiteral("2026-12-05T12:00:00Z"))));
    QVERIFY(written.left.isEmpty());
    const ElementSetText read = readElementSets(written.bytes);
    QCOMPARE(read.form, form);
    QVERIFY2(read.read.refusals.isEmpty(), qPrintable(read.read.refusals.value(0).reason));
    QCOMPARE(read.read.sets.size(), sets.size());
    for (qsizetype i = 0; i < sets.size(); ++i) {
        QString why;
        QVERIFY2(sameSet(read.read.sets[i], sets[i], &why), qPrintable(why));
    }
}

void TestGpForms::exportedTlesRoundTripAndNameWhatTheyCannotCarry()
{
    const QList<ElementSet> sets = readElementSetFile(kData + QStringLiteral("gp-2018.csv")).sets;
    const WrittenElementSets first = writeElementSets(sets, ElementSetForm::Tle);
    QCOMPARE(first.left.size(), 1);
    QVERIFY2(first.left[0].contains(QStringLiteral("270033591")) && first.left[0].contains(QStringLiteral("339999")),
             qPrintable(first.left[0]));
    // The lines are the test file's own (the CSV was made from them).
    QCOMPARE(QString::fromUtf8(first.bytes), QString::fromUtf8(fileBytes(QStringLiteral("gp-2018.tle"))));
    const ElementSetRead back = readTleText(QString::fromUtf8(first.bytes));
    QVERIFY(back.refusals.isEmpty());
    QCOMPARE(numbersOf(back.sets), (QList<int>{24278, 125544, 115429, 236411}));
    QCOMPARE(writeElementSets(back.sets, ElementSetForm::Tle).bytes, first.bytes);

    // A set from an OMM, with more digits than a TLE prints: rounded to the
    // columns, then stable.
    ElementSet fine = sets[1];
    fine.inclinationDeg = 51.642449999;
    fine.bstar = 3.855549e-5;
    fine.epochDayFraction = 0.5;
    fine.catalogueNumber = 339999;
    const WrittenElementSets rounded = writeElementSets({fine}, ElementSetForm::Tle);
    QVERIFY(rounded.bytes.contains("\n1 Z9999U 98067A   18020.50000000 "));
    QVERIFY(rounded.bytes.contains(" 51.6424 "));
    QVERIFY(rounded.bytes.contains(" 38555-4 "));
    QCOMPARE(writeElementSets(readTleText(QString::fromUtf8(rounded.bytes)).sets, ElementSetForm::Tle).bytes,
             rounded.bytes);
}

void TestGpForms::alpha5_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("number");
    QTest::newRow("digits") << QStringLiteral("25544") << 25544;
    QTest::newRow("A0000") << QStringLiteral("A0000") << 100000;
    QTest::newRow("H9999") << QStringLiteral("H9999") << 179999;
    QTest::newRow("J0000: I is skipped") << QStringLiteral("J0000") << 180000;
    QTest::newRow("P0000: O is skipped") << QStringLiteral("P0000") << 230000;
    QTest::newRow("Z9999") << QStringLiteral("Z9999") << 339999;
    QTest::newRow("lower case") << QStringLiteral("c5544") << 125544;
    QTest::newRow("nine digits") << QStringLiteral("270033591") << 270033591;
    QTest::newRow("I is no letter of it") << QStringLiteral("I0000") << -1;
    QTest::newRow("O is no letter of it") << QStringLiteral("O1234") << -1;
    QTest::newRow("ten digits") << QStringLiteral("1234567890") << -1;
    QTest::newRow("a name") << QStringLiteral("AO-91") << -1;
}

void TestGpForms::alpha5()
{
    QFETCH(QString, text);
    QFETCH(int, number);
    QCOMPARE(catalogueNumberFromAlpha5(text).value_or(-1), number);
    if (number >= 0 && number <= 339999 && text[0].isLetter())
        QCOMPARE(alpha5FromCatalogueNumber(number).value_or(QString()), text.toUpper());
    QVERIFY(!alpha5FromCatalogueNumber(340000));
}

void TestGpForms::epochs_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<double>("julianDay");
    QTest::addColumn<double>("fraction"); // -1: refused
    QTest::newRow("calendar date") << QStringLiteral("2008-09-20T12:25:40.104192") << 2454729.5 << 0.51782528;
    QTest::newRow("day of the year, Z") << QStringLiteral("2008-264T12:25:40.104192Z") << 2454729.5 << 0.51782528;
    QTest::newRow("no fraction") << QStringLiteral("2026-07-11T00:00:00") << 2461232.5 << 0.0;
    QTest::newRow("nanoseconds") << QStringLiteral("2026-07-11T00:00:00.000000001") << 2461232.5 << 1.0 / 86400e9;
    QTest::newRow("leap day") << QStringLiteral("2024-02-29T06:00:00") << 2460369.5 << 0.25;
    QTest::newRow("no leap day") << QStringLiteral("2026-02-29T06:00:00") << 0.0 << -1.0;
    QTest::newRow("hour 24") << QStringLiteral("2026-07-11T24:00:00") << 0.0 << -1.0;
    QTest::newRow("a date alone") << QStringLiteral("2026-07-11") << 0.0 << -1.0;
    QTest::newRow("nan") << QStringLiteral("nan") << 0.0 << -1.0;
    QTest::newRow("before Sputnik") << QStringLiteral("1900-01-01T00:00:00") << 0.0 << -1.0;
    QTest::newRow("a local time") << QStringLiteral("2026-07-11T00:00:00+02:00") << 0.0 << -1.0;
}

void TestGpForms::epochs()
{
    QFETCH(QString, text);
    QFETCH(double, julianDay);
    QFETCH(double, fraction);
    const std::optional<EpochParts> parts = epochFromText(text);
    if (fraction < 0) {
        QVERIFY(!parts);
        return;
    }
    QVERIFY(parts);
    QCOMPARE(parts->julianDay, julianDay);
    QCOMPARE(parts->dayFraction, fraction);
    ElementSet s;
    s.epochJulianDay = parts->julianDay;
    s.epochDayFraction = parts->dayFraction;
    QCOMPARE(epochFromText(epochText(s))->dayFraction, fraction);
}

void TestGpForms::csvByItsHeaderInAnyOrder()
{
    // Columns in another order, LF line ends, a byte-order mark, an extra
    // column, a quoted name with a comma and a quote, blank lines, Space-
    // Track's empty cells for what it does not know.
    const QByteArray text = "\xef\xbb\xbf" "NORAD_CAT_ID,EPOCH,MEAN_MOTION,ECCENTRICITY,INCLINATION,RA_OF_ASC_NODE,"
                            "ARG_OF_PERICENTER,MEAN_ANOMALY,BSTAR,RCS_SIZE,OBJECT_NAME,MEAN_MOTION_DDOT\n"
                            "\n"
                            "100001,2026-07-11T00:00:00,15,0,51.6,1,2,3,1e-4,SMALL,\"CUBE, \"\"ONE\"\"\",\n"
                            "100002,2026-07-11T00:00:00,15,0,51.6,1,2,3,1e-4,,PLAIN,0\n";
    const ElementSetText read = readElementSets(text);
    QCOMPARE(read.form, ElementSetForm::Csv);
    QVERIFY2(read.read.refusals.isEmpty(), qPrintable(read.read.refusals.value(0).reason));
    QCOMPARE(read.read.sets.size(), 2);
    QCOMPARE(read.read.sets[0].name, QStringLiteral("CUBE, \"ONE\""));
    QCOMPARE(read.read.sets[0].catalogueNumber, 100001);
    QCOMPARE(read.read.sets[0].meanMotionDdot, 0.0);
    QCOMPARE(read.read.sets[1].name, QStringLiteral("PLAIN"));

    // A header without what SGP4 needs is no GP file: said once, at line 1.
    const ElementSetRead noEpoch = readGpCsv(QStringLiteral("OBJECT_NAME,NORAD_CAT_ID\nX,1\n"));
    QCOMPARE(noEpoch.refusals.size(), 1);
    QCOMPARE(noEpoch.refusals[0].line, 1);
    QVERIFY2(noEpoch.refusals[0].reason.contains(QStringLiteral("no EPOCH, MEAN_MOTION")),
             qPrintable(noEpoch.refusals[0].reason));
}

void TestGpForms::badRowsAreRefusedAndTheRestLoads_data()
{
    QTest::addColumn<QByteArray>("row");
    QTest::addColumn<QString>("reason");
    const QByteArray good = csvRow(100003);
    QTest::newRow("nan") << QByteArray(good).replace("15.2", "nan") << QStringLiteral("MEAN_MOTION 'nan' is not a finite number");
    QTest::newRow("1e999") << QByteArray(good).replace(",97.5,", ",1e999,") << QStringLiteral("INCLINATION '1e999' is not a");
    QTest::newRow("out of range") << QByteArray(good).replace(",97.5,", ",197.5,") << QStringLiteral("INCLINATION 197.5° is outside 0..180°");
    QTest::newRow("missing field") << QByteArray(good).replace(",.00012,", ",,") << QStringLiteral("no BSTAR");
    QTest::newRow("short row") << QByteArray("NEW SAT,2026-150A,2026-07-11T12:34:56\r\n") << QStringLiteral("a short row: 3 fields where the header has 17");
    QTest::newRow("long row") << QByteArray(good).replace("\r\n", ",x\r\n") << QStringLiteral("a long row: 18 fields");
    QTest::newRow("number too long") << QByteArray(good).replace(",100003,", ",1000000000,") << QStringLiteral("NORAD_CAT_ID 1000000000");
    QTest::newRow("bad epoch") << QByteArray(good).replace("2026-07-11T12", "2026-13-11T12") << QStringLiteral("EPOCH '2026-13-11T12:34:56.123456' is not a UTC time");
    QTest::newRow("open quote") << QByteArray("\"NEW SAT,2026-150A\r\n") << QStringLiteral("a quoted field is not closed");
}

void TestGpForms::badRowsAreRefusedAndTheRestLoads()
{
    QFETCH(QByteArray, row);
    QFETCH(QString, reason);
    const bool lastRow = row.startsWith('"'); // an open quote takes the rest of the file
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("gp.csv"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(kCsvHeader + csvRow(100001) + (lastRow ? csvRow(100002) + row : row + csvRow(100002)));
    file.close();
    const ElementSetFile read = readElementSetFile(path);
    QCOMPARE(read.refusals.size(), 1);
    QCOMPARE(read.refusals[0].line, lastRow ? 4 : 3);
    QVERIFY2(read.refusals[0].reason.startsWith(reason), qPrintable(read.refusals[0].reason));
    QCOMPARE(numbersOf(read.sets), (QList<int>{100001, 100002}));
}

void TestGpForms::xmlWithADoctypeOrEntitiesIsRefusedAtOnce()
{
    const QByteArray good = fileBytes(QStringLiteral("gp-2018.xml"));
    QVERIFY(!good.isEmpty());
    // "A billion laughs": refused before anything is expanded.
    QByteArray laughs = "<?xml version=\"1.0\"?>\n<!DOCTYPE ndm [\n <!ENTITY a \"aaaaaaaaaa\">\n";
    for (char c = 'b'; c <= 'j'; ++c)
        laughs += QByteArray(" <!ENTITY ") + c + " \"" + QByteArray(10, '&').replace("&", QByteArray("&") + char(c - 1) + ";") + "\">\n";
    laughs += "]>\n" + good.mid(good.indexOf("<ndm")).replace("<OBJECT_NAME>FO-29 (JAS-2)", "<OBJECT_NAME>&j;");
    ElementSetRead read = readOmmXml(laughs);
    QVERIFY(read.sets.isEmpty());
    QCOMPARE(read.refusals.size(), 1);
    QVERIFY2(read.refusals[0].reason.contains(QStringLiteral("document type declaration")), qPrintable(read.refusals[0].reason));
    QVERIFY(read.refusals[0].line >= 2); // where the declaration ends

    // An external entity, the other attack: the same.
    read = readOmmXml("<?xml version=\"1.0\"?><!DOCTYPE ndm SYSTEM \"file:///etc/passwd\"><ndm/>");
    QVERIFY(read.sets.isEmpty());
    QVERIFY(read.refusals.value(0).reason.contains(QStringLiteral("document type declaration")));
    // An entity never declared is refused too, and nothing is read, not
    // even the sets before it.
    read = readOmmXml(QByteArray(good).replace("<OBJECT_NAME>GP TEST GEO-6", "<OBJECT_NAME>&x;"));
    QVERIFY(read.sets.isEmpty());
    QCOMPARE(read.refusals.size(), 1);
    QVERIFY2(read.refusals[0].reason.contains(QStringLiteral("refers to an entity 'x'")), qPrintable(read.refusals[0].reason));
    // A control character is only a broken file: the sets before it stay.
    read = readOmmXml(QByteArray(good).replace("<OBJECT_NAME>GP TEST GEO-6", "<OBJECT_NAME>GP\x01TEST"));
    QCOMPARE(read.sets.size(), 4);
    QCOMPARE(read.refusals.size(), 1);
    QVERIFY2(read.refusals[0].reason.contains(QStringLiteral("a control character (0x01)")), qPrintable(read.refusals[0].reason));
    // The five predefined ones are text, not entities to refuse.
    read = readOmmXml(QByteArray(good).replace("<OBJECT_NAME>FO-29 (JAS-2)", "<OBJECT_NAME>FO-29 &amp; &lt;JAS-2&gt;"));
    QVERIFY(read.refusals.isEmpty());
    QCOMPARE(read.sets[0].name, QStringLiteral("FO-29 & <JAS-2>"));
}

void TestGpForms::xmlTooDeepOrBrokenKeepsWhatCameBefore()
{
    const QByteArray good = fileBytes(QStringLiteral("gp-2018.xml"));
    // Cut inside the third OMM: the two before it are read, the break is named.
    const qsizetype third = good.indexOf("<omm", good.indexOf("<omm", good.indexOf("<omm") + 1) + 1);
    ElementSetRead read = readOmmXml(good.left(third + 200));
    QCOMPARE(read.sets.size(), 2);
    QCOMPARE(read.refusals.size(), 1);
    QVERIFY2(read.refusals[0].reason.contains(QStringLiteral("not well-formed")), qPrintable(read.refusals[0].reason));
    QVERIFY(read.refusals[0].line >= 4);

    QByteArray deep = "<ndm>";
    for (int i = 0; i < 40; ++i)
        deep += "<x>";
    read = readOmmXml(deep);
    QVERIFY(read.sets.isEmpty());
    QVERIFY2(read.refusals.value(0).reason.contains(QStringLiteral("nested deeper than 16")),
             qPrintable(read.refusals.value(0).reason));

    read = readOmmXml("<html><body>rate limited</body></html>");
    QVERIFY(read.sets.isEmpty());
    QVERIFY2(read.refusals.value(0).reason.contains(QStringLiteral("no <omm>")), qPrintable(read.refusals.value(0).reason));
}

void TestGpForms::jsonRefusalsNameTheEntry()
{
    QByteArray text = fileBytes(QStringLiteral("gp-2018.json"));
    text.replace("\"MEAN_MOTION\":14.12247534", "\"MEAN_MOTION\":\"nan\"");
    text.replace("\"NORAD_CAT_ID\":115429", "\"NORAD_CAT_ID\":115429.5");
    const ElementSetRead read = readGpJson(text);
    QCOMPARE(read.sets.size(), 3);
    QCOMPARE(read.refusals.size(), 2);
    QCOMPARE(read.refusals[0].place(), QStringLiteral("entry 3"));
    QCOMPARE(read.refusals[0].reason, QStringLiteral("MEAN_MOTION 'nan' is not a finite number"));
    QCOMPARE(read.refusals[1].place(), QStringLiteral("entry 4"));
    QVERIFY2(read.refusals[1].reason.contains(QStringLiteral("not a whole number")), qPrintable(read.refusals[1].reason));

    const ElementSetRead broken = readGpJson("[\n{\"NORAD_CAT_ID\": 1},\n{\"NORAD_CAT_ID\": }\n]");
    QVERIFY(broken.sets.isEmpty());
    QCOMPARE(broken.refusals.size(), 1);
    QCOMPARE(broken.refusals[0].line, 3);
    QVERIFY(broken.refusals[0].reason.startsWith(QStringLiteral("not JSON")));
}

void TestGpForms::kvnUnitsCommentsAndMessagesWithoutVersionLines()
{
    const QString text = QStringLiteral("COMMENT two messages, no version lines\n"
                                        "OBJECT_NAME = NOAA 16 [-]\n"
                                        "NORAD_CAT_ID = 26536\n"
                                        "EPOCH = 2026-07-11T00:00:00\n"
                                        "MEAN_MOTION = 14.1 [rev/day]\n"
                                        "ECCENTRICITY = 0.001\n"
                                        "INCLINATION = 99 [deg]\n"
                                        "RA_OF_ASC_NODE = 1\n"
                                        "ARG_OF_PERICENTER = 2\n"
                                        "MEAN_ANOMALY = 3\n"
                                        "BSTAR = 0 [1/ER]\n"
                                        "OBJECT_NAME = SECOND\n"
                                        "NORAD_CAT_ID = 26537\n"
                                        "EPOCH = 2026-07-11T00:00:00\n"
                                        "this line is wrong\n");
    const ElementSetRead read = readOmmKvn(text);
    QCOMPARE(read.sets.size(), 1);
    QCOMPARE(read.sets[0].name, QStringLiteral("NOAA 16 [-]")); // a name keeps its brackets
    QCOMPARE(read.sets[0].meanMotionRevPerDay, 14.1);
    QCOMPARE(read.refusals.size(), 1);
    QCOMPARE(read.refusals[0].line, 15);
    QVERIFY2(read.refusals[0].reason.contains(QStringLiteral("KEYWORD = value")), qPrintable(read.refusals[0].reason));
}

void TestGpForms::otherTheoriesAndFramesAreRefused()
{
    QByteArray kvn = fileBytes(QStringLiteral("gp-2018.kvn"));
    const qsizetype second = kvn.indexOf("MEAN_ELEMENT_THEORY = SGP4", kvn.indexOf("MEAN_ELEMENT_THEORY") + 1);
    kvn.replace(second, 26, "MEAN_ELEMENT_THEORY = SGP4-XP");
    kvn.replace(kvn.lastIndexOf("REF_FRAME = TEME"), 16, "REF_FRAME = GCRF");
    ElementSetRead read = readOmmKvn(QString::fromUtf8(kvn));
    QCOMPARE(read.sets.size(), 3);
    QCOMPARE(read.refusals.size(), 2);
    QVERIFY2(read.refusals[0].reason.startsWith(QStringLiteral("MEAN_ELEMENT_THEORY 'SGP4-XP': only SGP4")),
             qPrintable(read.refusals[0].reason));
    QVERIFY2(read.refusals[1].reason.startsWith(QStringLiteral("REF_FRAME 'GCRF'")), qPrintable(read.refusals[1].reason));

    QByteArray csv = kCsvHeader + csvRow(100001);
    csv.replace(",0,U,", ",4,U,");
    read = readGpCsv(QString::fromUtf8(csv));
    QVERIFY(read.sets.isEmpty());
    QVERIFY2(read.refusals.value(0).reason.contains(QStringLiteral("SGP4-XP")), qPrintable(read.refusals.value(0).reason));
}

void TestGpForms::devicesAndFifosAreRefused()
{
    const ElementSetFile zero = readElementSetFile(QStringLiteral("/dev/zero"));
    QVERIFY(zero.sets.isEmpty());
    QVERIFY2(zero.error.contains(QStringLiteral("character device")), qPrintable(zero.error));
    QTemporaryDir dir;
    const QString fifo = dir.filePath(QStringLiteral("gp.csv"));
    QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
    const ElementSetFile read = readElementSetFile(fifo); // returns at once: no writer is waited for
    QVERIFY(read.sets.isEmpty());
    QVERIFY2(!read.error.isEmpty(), "a FIFO was read as a file");
}

void TestGpForms::formsAreToldByContent_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<ElementSetForm>("form");
    QTest::newRow("3LE") << fileBytes(QStringLiteral("gp-2018.tle")) << ElementSetForm::Tle;
    QTest::newRow("CSV") << fileBytes(QStringLiteral("gp-2018.csv")) << ElementSetForm::Csv;
    QTest::newRow("quoted CSV header") << QByteArray("\"OBJECT_NAME\",\"NORAD_CAT_ID\"\r\n") << ElementSetForm::Csv;
    QTest::newRow("XML") << fileBytes(QStringLiteral("gp-2018.xml")) << ElementSetForm::OmmXml;
    QTest::newRow("JSON array") << fileBytes(QStringLiteral("gp-2018.json")) << ElementSetForm::Json;
    QTest::newRow("JSON object") << QByteArray("\n  {\"NORAD_CAT_ID\": 1}") << ElementSetForm::Json;
    QTest::newRow("KVN") << fileBytes(QStringLiteral("gp-2018.kvn")) << ElementSetForm::OmmKvn;
    QTest::newRow("KVN without a version line") << QByteArray("OBJECT_NAME = X\n") << ElementSetForm::OmmKvn;
    QTest::newRow("a name with a comma is a TLE's") << QByteArray("SAT, THE FIRST\n1 ...") << ElementSetForm::Tle;
}

void TestGpForms::formsAreToldByContent()
{
    QFETCH(QByteArray, text);
    QFETCH(ElementSetForm, form);
    QVERIFY(!text.isEmpty());
    QCOMPARE(recogniseForm(text), form);
}

QTEST_GUILESS_MAIN(TestGpForms)
#include "tst_gpforms.moc"
