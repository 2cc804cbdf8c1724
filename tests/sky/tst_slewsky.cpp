// SPDX-License-Identifier: GPL-3.0-or-later
// `slew --passes` and `slew --where` as the real program: the answers match
// the library's, the table and JSON forms both work, and bad input is
// refused with a message and exit status 2 (1 when there is nothing to
// answer with).

#include "sky/tleformat.h"
#include "sky/observation.h"
#include "sky/passes.h"
#include "sky/sgp4.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>
#include <QTimeZone>

#include <sys/stat.h>

using namespace slew::sky;

namespace {

const QString kTle = QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle");
// A day inside the snapshot's epochs.
const QString kStart = QStringLiteral("2018-01-21T00:00:00Z");

struct Run {
    int exitCode = -1;
    QByteArray out, err;
};

Run runSlew(const QStringList &arguments, const QString &configHome = QString())
{
    Run r;
    QProcess p;
    // Settings from a directory of the test's, never the user's own.
    static QTemporaryDir emptyHome;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), configHome.isEmpty() ? emptyHome.path() : configHome);
    p.setProcessEnvironment(env);
    p.start(qEnvironmentVariable("SLEW_BIN"), arguments);
    if (!p.waitForFinished(120000))
        return r;
    r.exitCode = p.exitCode();
    r.out = p.readAllStandardOutput();
    r.err = p.readAllStandardError();
    return r;
}

double julianOf(const QString &iso)
{
    return julianFromUnixSeconds(QDateTime::fromString(iso, Qt::ISODate).toMSecsSinceEpoch() / 1000.0);
}

} // namespace

class TestSlewSky : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void passesAsJson();
    void passesOfAllSortedByAos();
    void passesTable();
    void sunRiseAndSet();
    void whereMatchesTheLibrary();
    void whereSunAndMoon();
    void refusals_data();
    void refusals();
    void helpDescribesTheMode();
    void savedStationWhenNoQth();
    void theOperatorsOwnSatelliteNames();
    void qthGivenToTheWindowIsKept();
    void qthInTheStationServiceConfig();
    void concatenatedFilesCountEachSatelliteOnce();
    void setsThatAreNotNumbersAreSkippedSayingWhy();
    void timeAndStartAreOneOption();
};

void TestSlewSky::initTestCase()
{
    QVERIFY2(!qEnvironmentVariable("SLEW_BIN").isEmpty(), "SLEW_BIN is not set (tests/CMakeLists.txt sets it)");
    QVERIFY(QFile::exists(kTle));
}

void TestSlewSky::passesAsJson()
{
    const Run r = runSlew({QStringLiteral("--passes"), QStringLiteral("iss"), QStringLiteral("--qth"),
                        QStringLiteral("JO65hq"), QStringLiteral("--tle"), kTle, QStringLiteral("--start"), kStart,
                        QStringLiteral("--hours"), QStringLiteral("24"), QStringLiteral("--min-el"),
                        QStringLiteral("10"), QStringLiteral("--json")});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QJsonArray passes = QJsonDocument::fromJson(r.out).array();
    QVERIFY(passes.size() >= 2);

    // The same passes as the library gives.
    QList<ElementSet> sets = readTleText([] {
                          QFile f(kTle);
                          f.open(QIODevice::ReadOnly);
                          return QString::fromLatin1(f.readAll());
                      }())
                          .sets;
    const ElementSet *iss = findSatellites(sets, QStringLiteral("ISS")).first();
    const double start = julianOf(kStart);
    // AOS and LOS at the horizon, and only the passes that climb to 10°.
    QList<Pass> expected = predictPasses(Sgp4(*iss), Site{55.6875, 12.625, 0, {}, {}}, {start, start + 1.0, 0.0});
    const qsizetype all = expected.size();
    expected.removeIf([](const Pass &p) { return p.maxElevationDeg() < 10.0; });
    QVERIFY(expected.size() < all); // some low pass was left out
    QCOMPARE(passes.size(), expected.size());
    for (int i = 0; i < passes.size(); ++i) {
        const QJsonObject p = passes[i].toObject();
        QCOMPARE(p.value(QStringLiteral("name")).toString(), QStringLiteral("ISS (ZARYA)"));
        QCOMPARE(p.value(QStringLiteral("catalogue_number")).toInt(), 25544);
        const double aos = julianOf(p.value(QStringLiteral("aos")).toObject().value(QStringLiteral("time")).toString());
        QVERIFY(std::fabs(aos - expected[i].aos.julian) * kSecondsPerDay < 1.0);
        QVERIFY(p.value(QStringLiteral("max_elevation")).toDouble() >= 10.0);
        QVERIFY(std::fabs(p.value(QStringLiteral("max_elevation")).toDouble() - expected[i].maxElevationDeg()) < 0.06);
        QVERIFY(p.contains(QStringLiteral("sunlit")));
        QVERIFY(p.value(QStringLiteral("los")).toObject().contains(QStringLiteral("azimuth")));
    }
}

void TestSlewSky::passesOfAllSortedByAos()
{
    const Run r = runSlew({QStringLiteral("--passes"), QStringLiteral("all"), QStringLiteral("--qth"),
                        QStringLiteral("55.6875,12.625,20"), QStringLiteral("--tle"), kTle, QStringLiteral("--start"),
                        kStart, QStringLiteral("--hours"), QStringLiteral("1"), QStringLiteral("--json")});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QJsonArray passes = QJsonDocument::fromJson(r.out).array();
    QVERIFY(passes.size() > 20);
    QSet<int> satellites;
    QString previous;
    for (const QJsonValue &v : passes) {
        const QJsonObject p = v.toObject();
        const QString aos = p.value(QStringLiteral("aos")).toObject().value(QStringLiteral("time")).toString();
        QVERIFY(previous <= aos); // ISO 8601 in UTC sorts as text
        previous = aos;
        satellites.insert(p.value(QStringLiteral("catalogue_number")).toInt());
    }
    QVERIFY(satellites.size() > 10);
}

void TestSlewSky::passesTable()
{
    const Run r = runSlew({QStringLiteral("--passes"), QStringLiteral("25544"), QStringLiteral("--qth"),
                        QStringLiteral("JO65hq"), QStringLiteral("--tle"), kTle, QStringLiteral("--start"), kStart});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QList<QByteArray> lines = r.out.trimmed().split('\n');
    QVERIFY(lines.size() >= 3);
    QVERIFY(lines[0].startsWith("Satellite"));
    QVERIFY(lines[0].contains("AOS (UTC)") && lines[0].contains("Max el") && lines[0].contains("Sunlit"));
    QVERIFY(lines[1].startsWith("ISS (ZARYA)"));
    QVERIFY(lines[1].contains("2018-01-21"));
}

void TestSlewSky::sunRiseAndSet()
{
    const Run r = runSlew({QStringLiteral("--passes"), QStringLiteral("sun"), QStringLiteral("--qth"),
                        QStringLiteral("51.4779,-0.0015"), QStringLiteral("--start"),
                        QStringLiteral("2024-06-20T00:00:00Z"), QStringLiteral("--hours"), QStringLiteral("24"),
                        QStringLiteral("--json")});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QJsonArray passes = QJsonDocument::fromJson(r.out).array();
    QCOMPARE(passes.size(), 1);
    const QJsonObject day = passes[0].toObject();
    // Greenwich, 20 June 2024: London's published sunrise and sunset are
    // 04:43 and 21:21 BST; the sun culminates at 90 − 51.48 + 23.44 = 62.0°.
    // Published to the minute: within half a minute of it.
    const double rise = julianOf(day.value(QStringLiteral("aos")).toObject().value(QStringLiteral("time")).toString());
    const double set = julianOf(day.value(QStringLiteral("los")).toObject().value(QStringLiteral("time")).toString());
    QVERIFY(std::fabs(rise - julianOf(QStringLiteral("2024-06-20T03:43:00Z"))) * kSecondsPerDay <= 30.0);
    QVERIFY(std::fabs(set - julianOf(QStringLiteral("2024-06-20T20:21:00Z"))) * kSecondsPerDay <= 30.0);
    QVERIFY(std::fabs(day.value(QStringLiteral("max_elevation")).toDouble() - 62.0) < 0.2);
}

void TestSlewSky::whereMatchesTheLibrary()
{
    const QString when = QStringLiteral("2018-01-21T12:34:56Z");
    const Run r = runSlew({QStringLiteral("--where"), QStringLiteral("ISS (ZARYA)"), QStringLiteral("--qth"),
                        QStringLiteral("JO65hq"), QStringLiteral("--tle"), kTle, QStringLiteral("--time"), when,
                        QStringLiteral("--json")});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QJsonObject o = QJsonDocument::fromJson(r.out).object();

    QFile f(kTle);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QList<ElementSet> sets = readTleText(QString::fromLatin1(f.readAll())).sets;
    const Sgp4 iss(*findSatellites(sets, QStringLiteral("25544")).first());
    const double jd = julianOf(when);
    const Sgp4State s = iss.propagateToJulian(jd);
    const LookAngles look = lookAngles(Site{55.6875, 12.625, 0, {}, {}}, s.positionKm, s.velocityKmS, jd);
    QVERIFY(std::fabs(o.value(QStringLiteral("azimuth")).toDouble() - look.azimuthDeg) < 1e-6);
    QVERIFY(std::fabs(o.value(QStringLiteral("elevation")).toDouble() - look.elevationDeg) < 1e-6);
    QVERIFY(std::fabs(o.value(QStringLiteral("range_km")).toDouble() - look.rangeKm) < 1e-6);
    QVERIFY(std::fabs(o.value(QStringLiteral("range_rate_km_s")).toDouble() - look.rangeRateKmS) < 1e-9);
    QVERIFY(std::fabs(o.value(QStringLiteral("altitude_km")).toDouble() - 405) < 30);
    QVERIFY(o.contains(QStringLiteral("sunlit")));

    // Refraction lifts the elevation by the formula's amount.
    const Run refracted = runSlew({QStringLiteral("--where"), QStringLiteral("25544"), QStringLiteral("--qth"),
                                QStringLiteral("JO65hq"), QStringLiteral("--tle"), kTle, QStringLiteral("--time"), when,
                                QStringLiteral("--refraction"), QStringLiteral("--json")});
    QCOMPARE(refracted.exitCode, 0);
    const double lifted = QJsonDocument::fromJson(refracted.out).object().value(QStringLiteral("elevation")).toDouble();
    QVERIFY(std::fabs(lifted - (look.elevationDeg + refractionDeg(look.elevationDeg))) < 1e-6);

    // The text form says the same.
    const Run text = runSlew({QStringLiteral("--where"), QStringLiteral("25544"), QStringLiteral("--qth"),
                           QStringLiteral("JO65hq"), QStringLiteral("--tle"), kTle, QStringLiteral("--time"), when});
    QCOMPARE(text.exitCode, 0);
    QVERIFY(text.out.contains("azimuth    " + QByteArray::number(look.azimuthDeg, 'f', 3)));
    QVERIFY(text.out.contains("range-rate"));
}

void TestSlewSky::whereSunAndMoon()
{
    for (const QString &body : {QStringLiteral("sun"), QStringLiteral("Moon")}) {
        const Run r = runSlew({QStringLiteral("--where"), body, QStringLiteral("--qth"), QStringLiteral("FN31pr"),
                            QStringLiteral("--time"), QStringLiteral("2024-06-20T12:00:00Z"), QStringLiteral("--json")});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        const Site s{41.729166666, -72.708333333, 0, {}, {}};
        const BodyPosition p = bodyPosition(body == u"sun" ? SkyBody::Sun : SkyBody::Moon, s, 2460482.0);
        QVERIFY(std::fabs(o.value(QStringLiteral("azimuth")).toDouble() - p.azimuthDeg) < 1e-6);
        QVERIFY(std::fabs(o.value(QStringLiteral("elevation")).toDouble() - p.elevationDeg) < 1e-6);
        // Range within the earth's radius of the centre distance; the sun's
        // range-rate is under 1 km/s, the moon's under 2.
        QVERIFY(std::fabs(o.value(QStringLiteral("range_km")).toDouble() - p.distanceKm) < 6400);
        QVERIFY(std::fabs(o.value(QStringLiteral("range_rate_km_s")).toDouble()) < 2.0);
    }
}

void TestSlewSky::refusals_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("message");
    const QStringList tle{QStringLiteral("--tle"), kTle};
    QTest::newRow("bad locator") << (QStringList{QStringLiteral("--where"), QStringLiteral("sun"),
                                                 QStringLiteral("--qth"), QStringLiteral("ZZ99")})
                                 << 2 << QStringLiteral("letters A to R");
    QTest::newRow("no station") << (QStringList{QStringLiteral("--where"), QStringLiteral("sun")}) << 2
                                << QStringLiteral("--qth is needed");
    QTest::newRow("satellite without elements")
        << (QStringList{QStringLiteral("--passes"), QStringLiteral("ISS"), QStringLiteral("--qth"), QStringLiteral("JO65")})
        << 2 << QStringLiteral("no element sets: give --tle FILE, or refresh the window's sources");
    QTest::newRow("bad time") << (QStringList{QStringLiteral("--where"), QStringLiteral("moon"), QStringLiteral("--qth"),
                                              QStringLiteral("JO65"), QStringLiteral("--time"), QStringLiteral("noon")})
                              << 2 << QStringLiteral("ISO 8601");
    QTest::newRow("hours out of range")
        << (QStringList{QStringLiteral("--passes"), QStringLiteral("sun"), QStringLiteral("--qth"), QStringLiteral("JO65"),
                        QStringLiteral("--hours"), QStringLiteral("0")})
        << 2 << QStringLiteral("--hours");
    QTest::newRow("no such satellite") << (QStringList{QStringLiteral("--where"), QStringLiteral("VOYAGER"),
                                                       QStringLiteral("--qth"), QStringLiteral("JO65")}
                                           + tle)
                                       << 1 << QStringLiteral("no satellite 'VOYAGER'");
    QTest::newRow("ambiguous name") << (QStringList{QStringLiteral("--where"), QStringLiteral("NOAA"),
                                                    QStringLiteral("--qth"), QStringLiteral("JO65")}
                                        + tle)
                                    << 1 << QStringLiteral("matches");
    QTest::newRow("missing file") << (QStringList{QStringLiteral("--passes"), QStringLiteral("ISS"),
                                                  QStringLiteral("--qth"), QStringLiteral("JO65"), QStringLiteral("--tle"),
                                                  QStringLiteral("/nonexistent/elements.txt")})
                                  << 2 << QStringLiteral("/nonexistent/elements.txt");

    // Numbers that are not finite: Qt reads "nan" and "inf" as numbers, and
    // each of these once passed its range check and hung the search.
    const QStringList sun{QStringLiteral("--passes"), QStringLiteral("sun")};
    const QStringList jo65{QStringLiteral("--qth"), QStringLiteral("JO65")};
    QTest::newRow("qth nan") << (sun + QStringList{QStringLiteral("--qth"), QStringLiteral("nan,0")}) << 2
                             << QStringLiteral("must be finite numbers");
    QTest::newRow("qth inf height") << (sun + QStringList{QStringLiteral("--qth"), QStringLiteral("55,12,inf")}) << 2
                                    << QStringLiteral("must be finite numbers");
    QTest::newRow("min-el nan") << (sun + jo65 + QStringList{QStringLiteral("--min-el"), QStringLiteral("nan")}) << 2
                                << QStringLiteral("--min-el: 'nan' is not a finite number");
    QTest::newRow("hours nan") << (sun + jo65 + QStringList{QStringLiteral("--hours"), QStringLiteral("nan")}) << 2
                               << QStringLiteral("--hours: 'nan' is not a finite number");
    QTest::newRow("hours inf") << (sun + jo65 + QStringList{QStringLiteral("--hours"), QStringLiteral("inf")}) << 2
                               << QStringLiteral("--hours: 'inf' is not a finite number");
    QTest::newRow("where qth nan") << (QStringList{QStringLiteral("--where"), QStringLiteral("moon"), QStringLiteral("--qth"),
                                                   QStringLiteral("0,nan")})
                                   << 2 << QStringLiteral("must be finite numbers");

    // Files that are not files: /dev/zero reads for ever (QFile::size() is
    // 0), a FIFO with no writer blocks open() for ever.
    static QTemporaryDir fifoDir;
    const QString fifo = fifoDir.filePath(QStringLiteral("elements.fifo"));
    if (!QFile::exists(fifo))
        ::mkfifo(QFile::encodeName(fifo).constData(), 0600);
    const QStringList iss{QStringLiteral("--passes"), QStringLiteral("ISS")};
    QTest::newRow("tle /dev/zero") << (iss + jo65 + QStringList{QStringLiteral("--tle"), QStringLiteral("/dev/zero")}) << 2
                                   << QStringLiteral("/dev/zero is a character device, not a file");
    QTest::newRow("tle fifo") << (iss + jo65 + QStringList{QStringLiteral("--tle"), fifo}) << 2
                              << QStringLiteral("is a FIFO (named pipe), not a file");
    QTest::newRow("where tle fifo") << (QStringList{QStringLiteral("--where"), QStringLiteral("ISS")} + jo65
                                        + QStringList{QStringLiteral("--tle"), fifo})
                                    << 2 << QStringLiteral("FIFO");

    // The station service: the same rule for its options.
    const QStringList headless{QStringLiteral("--headless"), QStringLiteral("--connect"), QStringLiteral("sim:"),
                               QStringLiteral("--qth"), QStringLiteral("JO65")};
    QTest::newRow("service track ambiguous")
        << (headless + QStringList{QStringLiteral("--track"), QStringLiteral("NOAA")} + tle) << 2
        << QStringLiteral("'NOAA' matches");
    QTest::newRow("service min-el nan")
        << (headless + QStringList{QStringLiteral("--track"), QStringLiteral("sun"), QStringLiteral("--min-el"),
                                   QStringLiteral("nan")})
        << 2 << QStringLiteral("--min-el: 'nan' is not a finite number");
    QTest::newRow("service clock-rate nan")
        << (headless + QStringList{QStringLiteral("--track"), QStringLiteral("sun"), QStringLiteral("--clock-start"),
                                   QStringLiteral("2024-06-20T12:00:00Z"), QStringLiteral("--clock-rate"),
                                   QStringLiteral("nan")})
        << 2 << QStringLiteral("--clock-rate: 'nan' is not a finite number");
    QTest::newRow("service qth nan")
        << (QStringList{QStringLiteral("--headless"), QStringLiteral("--qth"), QStringLiteral("nan,0")}) << 2
        << QStringLiteral("must be finite numbers");
    QTest::newRow("service azel nan")
        << (headless + QStringList{QStringLiteral("--track"), QStringLiteral("azel:nan,10")}) << 2
        << QStringLiteral("--track 'azel:nan,10'");
    QTest::newRow("service tle /dev/zero")
        << (headless + QStringList{QStringLiteral("--track"), QStringLiteral("ISS"), QStringLiteral("--tle"),
                                   QStringLiteral("/dev/zero")})
        << 2 << QStringLiteral("/dev/zero is a character device");
    QTest::newRow("service tle fifo")
        << (headless + QStringList{QStringLiteral("--track"), QStringLiteral("ISS"), QStringLiteral("--tle"), fifo}) << 2
        << QStringLiteral("FIFO");
    QTest::newRow("service profile /dev/zero")
        << (QStringList{QStringLiteral("--headless"), QStringLiteral("--profile"), QStringLiteral("/dev/zero")}) << 2
        << QStringLiteral("--profile: /dev/zero is a character device");
    QTest::newRow("service config fifo")
        << (QStringList{QStringLiteral("--headless"), QStringLiteral("--config"), fifo}) << 2
        << QStringLiteral("is a FIFO (named pipe)");
    QTest::newRow("window qth nan")
        << (QStringList{QStringLiteral("--qth"), QStringLiteral("nan,0"), QStringLiteral("--screenshot"),
                        fifoDir.filePath(QStringLiteral("never.png"))})
        << 2 << QStringLiteral("must be finite numbers");
    QTest::newRow("window goto nan")
        << (QStringList{QStringLiteral("--goto"), QStringLiteral("nan,10"), QStringLiteral("--screenshot"),
                        fifoDir.filePath(QStringLiteral("never.png"))})
        << 2 << QStringLiteral("--goto wants az,el as two numbers");
}

void TestSlewSky::refusals()
{
    QFETCH(QStringList, arguments);
    QFETCH(int, exitCode);
    QFETCH(QString, message);
    const Run r = runSlew(arguments);
    QCOMPARE(r.exitCode, exitCode);
    QVERIFY2(QString::fromUtf8(r.err).contains(message), r.err.constData());
}

void TestSlewSky::helpDescribesTheMode()
{
    const Run r = runSlew({QStringLiteral("--passes"), QStringLiteral("x"), QStringLiteral("--help")});
    QCOMPARE(r.exitCode, 0);
    QVERIFY(r.out.contains("--min-el"));
    QVERIFY(r.out.contains("--qth"));
}

void TestSlewSky::savedStationWhenNoQth()
{
    // What the window's Sky → Station… leaves in ~/.config/Slew/slew.conf.
    QTemporaryDir home;
    QVERIFY(QDir(home.path()).mkpath(QStringLiteral("Slew")));
    QFile conf(home.filePath(QStringLiteral("Slew/slew.conf")));
    QVERIFY(conf.open(QIODevice::WriteOnly));
    conf.write("[sky]\nstation=JO65hq\n");
    conf.close();
    const QStringList where{QStringLiteral("--where"), QStringLiteral("sun"), QStringLiteral("--time"),
                            QStringLiteral("2024-06-20T12:00:00Z"), QStringLiteral("--json")};
    const Run saved = runSlew(where, home.path());
    QVERIFY2(saved.exitCode == 0, saved.err.constData());
    const Run given = runSlew(where + QStringList{QStringLiteral("--qth"), QStringLiteral("JO65hq")});
    QCOMPARE(given.exitCode, 0);
    QCOMPARE(saved.out, given.out);

    // A bad saved station is refused with a pointer to --qth.
    QVERIFY(conf.open(QIODevice::WriteOnly));
    conf.write("[sky]\nstation=ZZ99\n");
    conf.close();
    const Run bad = runSlew(where, home.path());
    QCOMPARE(bad.exitCode, 2);
    QVERIFY2(bad.err.contains("give --qth"), bad.err.constData());
}

void TestSlewSky::theOperatorsOwnSatelliteNames()
{
    // ~/.config/Slew/satellite-names.txt adds names and takes back a
    // built-in one; a bad line is said with its place and skipped.
    QTemporaryDir home;
    QVERIFY(QDir(home.path()).mkpath(QStringLiteral("Slew")));
    QFile names(home.filePath(QStringLiteral("Slew/satellite-names.txt")));
    QVERIFY(names.open(QIODevice::WriteOnly));
    names.write("# mine\n25544  Space Station  # as the club calls it\nISS 25544\n25338 ARISS\n");
    names.close();
    const QStringList at{QStringLiteral("--qth"), QStringLiteral("JO65hq"), QStringLiteral("--tle"), kTle,
                         QStringLiteral("--time"), QStringLiteral("2018-01-21T12:34:56Z"), QStringLiteral("--json")};
    const auto numberWhere = [&](const QString &name, Run *run) {
        *run = runSlew(QStringList{QStringLiteral("--where"), name} + at, home.path());
        return QJsonDocument::fromJson(run->out).object().value(QStringLiteral("catalogue_number")).toInt();
    };
    Run r;
    QCOMPARE(numberWhere(QStringLiteral("space station"), &r), 25544);
    QVERIFY2(r.err.contains(qPrintable(names.fileName() + QStringLiteral(":3: 'ISS' is not a catalogue number"))),
             r.err.constData());
    QCOMPARE(numberWhere(QStringLiteral("ARISS"), &r), 25338); // the operator's, not the built-in 25544
    // A FIFO in its place is refused, not waited on; the built-in names stay.
    QTemporaryDir fifoHome;
    QVERIFY(QDir(fifoHome.path()).mkpath(QStringLiteral("Slew")));
    QVERIFY(::mkfifo(QFile::encodeName(fifoHome.filePath(QStringLiteral("Slew/satellite-names.txt"))).constData(), 0600) == 0);
    const Run fifo = runSlew(QStringList{QStringLiteral("--where"), QStringLiteral("ARISS")} + at, fifoHome.path());
    QCOMPARE(fifo.exitCode, 0);
    QVERIFY2(fifo.err.contains("satellite-names.txt") && fifo.err.contains("not read"), fifo.err.constData());
    QCOMPARE(QJsonDocument::fromJson(fifo.out).object().value(QStringLiteral("catalogue_number")).toInt(), 25544);
    // Without the file, the built-in names as before.
    QCOMPARE(QJsonDocument::fromJson(runSlew(QStringList{QStringLiteral("--where"), QStringLiteral("ARISS")} + at).out)
                 .object()
                 .value(QStringLiteral("catalogue_number"))
                 .toInt(),
             25544);
}

void TestSlewSky::qthGivenToTheWindowIsKept()
{
    // `slew --qth` sets the station as Sky → Station… does; the sky
    // commands then find it without --qth.
    QTemporaryDir home;
    const QStringList where{QStringLiteral("--where"), QStringLiteral("sun"), QStringLiteral("--time"),
                            QStringLiteral("2024-06-20T12:00:00Z"), QStringLiteral("--json")};
    QCOMPARE(runSlew(where, home.path()).exitCode, 2); // no station yet
    const Run window = runSlew({QStringLiteral("--qth"), QStringLiteral("FN31pr"), QStringLiteral("--screenshot"),
                                home.filePath(QStringLiteral("w.png")), QStringLiteral("--settle-ms"), QStringLiteral("0")},
                               home.path());
    QVERIFY2(window.exitCode == 0, window.err.constData());
    const Run saved = runSlew(where, home.path());
    QVERIFY2(saved.exitCode == 0, saved.err.constData());
    QCOMPARE(saved.out, runSlew(where + QStringList{QStringLiteral("--qth"), QStringLiteral("FN31pr")}).out);

    // A bad one is refused before the window opens, and the kept one stays.
    const Run bad = runSlew({QStringLiteral("--qth"), QStringLiteral("91,10"), QStringLiteral("--screenshot"),
                             home.filePath(QStringLiteral("x.png"))},
                            home.path());
    QCOMPARE(bad.exitCode, 2);
    QVERIFY2(bad.err.contains("--qth: latitude"), bad.err.constData());
    QVERIFY(!QFile::exists(home.filePath(QStringLiteral("x.png"))));
    QCOMPARE(runSlew(where, home.path()).out, saved.out);
}

void TestSlewSky::qthInTheStationServiceConfig()
{
    // `qth =` in a --config file is checked at start: a bad one stops the
    // service with the reason, before any link opens.
    QTemporaryDir dir;
    QFile conf(dir.filePath(QStringLiteral("station.conf")));
    QVERIFY(conf.open(QIODevice::WriteOnly));
    conf.write("connect = sim:\nqth = JO65zz\n");
    conf.close();
    const Run bad = runSlew({QStringLiteral("--headless"), QStringLiteral("--config"), conf.fileName()});
    QCOMPARE(bad.exitCode, 2);
    // The refusal names the file and the line the value came from.
    QVERIFY2(bad.err.contains(conf.fileName().toUtf8() + ":2: qth: locator \"JO65zz\""), bad.err.constData());
    QVERIFY2(bad.out.isEmpty(), bad.out.constData());
}

void TestSlewSky::concatenatedFilesCountEachSatelliteOnce()
{
    // Two group files put together, as operators do: the same 979 sets twice.
    QTemporaryDir dir;
    QFile original(kTle);
    QVERIFY(original.open(QIODevice::ReadOnly));
    const QByteArray text = original.readAll();
    QFile twice(dir.filePath(QStringLiteral("twice.tle")));
    QVERIFY(twice.open(QIODevice::WriteOnly));
    twice.write(text + "\n" + text);
    twice.close();

    const QStringList common{QStringLiteral("--qth"), QStringLiteral("55.6875,12.625,20"), QStringLiteral("--start"),
                             kStart, QStringLiteral("--hours"), QStringLiteral("1"), QStringLiteral("--json")};
    const Run one = runSlew(QStringList{QStringLiteral("--passes"), QStringLiteral("25544"), QStringLiteral("--tle"),
                                        twice.fileName()} + common);
    QVERIFY2(one.exitCode == 0, one.err.constData());
    QVERIFY2(one.err.contains("979 sets repeat a satellite listed before"), one.err.constData());

    const Run all = runSlew(QStringList{QStringLiteral("--passes"), QStringLiteral("all"), QStringLiteral("--tle"),
                                        twice.fileName()} + common);
    const Run single = runSlew(QStringList{QStringLiteral("--passes"), QStringLiteral("all"), QStringLiteral("--tle"),
                                           kTle} + common);
    QVERIFY2(all.exitCode == 0, all.err.constData());
    QCOMPARE(QJsonDocument::fromJson(all.out).array().size(), QJsonDocument::fromJson(single.out).array().size());
}

void TestSlewSky::setsThatAreNotNumbersAreSkippedSayingWhy()
{
    // A set whose mean motion reads "nan", its checksum right: it made the
    // pass search spin for ever. Now it is skipped with its line and reason,
    // and the good set beside it still has its passes.
    QTemporaryDir dir;
    QString nanLine2 = QStringLiteral("2 25544  51.6424  32.9776 0003646  28.7227  39.5332         nan 95614");
    int sum = 0;
    for (int i = 0; i < 68; ++i)
        sum += nanLine2[i].isDigit() ? nanLine2[i].digitValue() : (nanLine2[i] == u'-' ? 1 : 0);
    nanLine2[68] = QChar(u'0' + sum % 10);
    QFile file(dir.filePath(QStringLiteral("nan.tle")));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("BROKEN ISS\n1 25544U 98067A   18020.89808844  .00002078  00000-0  38550-4 0  9992\n"
               + nanLine2.toLatin1()
               + "\nNOAA 19\n1 33591U 09005A   18020.91958580  .00000107  00000-0  83477-4 0  9992\n"
                 "2 33591  99.1238 356.1693 0014450  24.0615 336.1228 14.12247534461122\n");
    file.close();
    const QStringList common{QStringLiteral("--qth"), QStringLiteral("55.6875,12.625,20"), QStringLiteral("--tle"),
                             file.fileName(), QStringLiteral("--start"), kStart, QStringLiteral("--json")};
    const Run all = runSlew(QStringList{QStringLiteral("--passes"), QStringLiteral("all")} + common);
    QVERIFY2(all.exitCode == 0, all.err.constData());
    QVERIFY2(all.err.contains(":3: skipped: mean motion"), all.err.constData());
    QVERIFY(!QJsonDocument::fromJson(all.out).array().isEmpty());

    // Tracking the broken one says why it is not there, as --passes does.
    const Run track = runSlew({QStringLiteral("--headless"), QStringLiteral("--connect"), QStringLiteral("sim:"),
                               QStringLiteral("--qth"), QStringLiteral("JO65"), QStringLiteral("--track"),
                               QStringLiteral("25544"), QStringLiteral("--tle"), file.fileName()});
    QCOMPARE(track.exitCode, 2);
    QVERIFY2(track.err.contains("no satellite '25544'") && track.err.contains(":3: skipped: mean motion"),
             track.err.constData());

    // The same in a GP file: the row's line, the keyword, the value.
    QFile csv(dir.filePath(QStringLiteral("gp.csv")));
    QVERIFY(csv.open(QIODevice::WriteOnly));
    csv.write("OBJECT_NAME,NORAD_CAT_ID,EPOCH,MEAN_MOTION,ECCENTRICITY,INCLINATION,RA_OF_ASC_NODE,ARG_OF_PERICENTER,"
              "MEAN_ANOMALY,BSTAR\n"
              "NOAA 19,33591,2018-01-20T22:04:12.213120,14.12247534,.0014450,99.1238,356.1693,24.0615,336.1228,.83477E-4\n"
              "BROKEN,125544,2018-01-20T21:33:14.841216,nan,.0003646,51.6424,32.9776,28.7227,39.5332,.38550E-4\n");
    csv.close();
    const Run gp = runSlew({QStringLiteral("--passes"), QStringLiteral("all"), QStringLiteral("--qth"),
                            QStringLiteral("JO65hq"), QStringLiteral("--tle"), csv.fileName(), QStringLiteral("--start"),
                            kStart});
    QVERIFY2(gp.exitCode == 0, gp.err.constData());
    QVERIFY2(gp.err.contains("gp.csv:3: skipped: MEAN_MOTION 'nan' is not a finite number\n"), gp.err.constData());
    QVERIFY2(gp.err.contains("gp.csv: 1 set (CSV)"), gp.err.constData());
    QVERIFY(gp.out.contains("NOAA 19"));
}

void TestSlewSky::timeAndStartAreOneOption()
{
    // --where took --time and --passes --start for the same idea: each now
    // takes both.
    const QStringList jo65{QStringLiteral("--qth"), QStringLiteral("JO65hq"), QStringLiteral("--json")};
    for (const QString &mode : {QStringLiteral("--where"), QStringLiteral("--passes")}) {
        const Run withTime = runSlew(QStringList{mode, QStringLiteral("sun"), QStringLiteral("--time"), kStart} + jo65);
        const Run withStart = runSlew(QStringList{mode, QStringLiteral("sun"), QStringLiteral("--start"), kStart} + jo65);
        QVERIFY2(withTime.exitCode == 0 && withStart.exitCode == 0, withTime.err + withStart.err);
        QCOMPARE(withTime.out, withStart.out);
        QVERIFY(withTime.out.contains(kStart.left(10).toUtf8()));
    }
}

QTEST_GUILESS_MAIN(TestSlewSky)
#include "tst_slewsky.moc"
