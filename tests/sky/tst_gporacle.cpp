// SPDX-License-Identifier: GPL-3.0-or-later
// Satellites with six- and nine-digit catalogue numbers, in every form an
// element set comes in, through the real program: `slew --where` and
// `slew --passes` read each file of tests/data/gp (CSV, OMM XML, JSON as
// CelesTrak and as Space-Track write it, OMM KVN, and TLE with Alpha-5
// numbers where a TLE can carry one), and their answers are held against
// Debian's python3-sgp4 reading the same elements through its own OMM
// reader (sgp4.omm), with its own sidereal time (Vallado's gstime) and the
// station on the WGS-84 ellipsoid, written out here in Python: an oracle
// that shares no code with Slew.

#include <QDateTime>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

namespace {

const QString kPython = QStringLiteral("/usr/bin/python3");
const QString kData = QStringLiteral(SLEW_TEST_DATA_DIR "/gp/");
const QString kQth = QStringLiteral("55.6875,12.625,20");
const QString kStart = QStringLiteral("2018-01-21T00:00:00Z");
const double kStartJulian = 2458139.5;
const int kHours = 24;

struct Satellite {
    const char *what;
    int number;
};
// A near-earth six-digit object, a nine-digit one, and a deep-space
// six-digit one (a Molniya orbit: SDP4's half-day resonance).
const Satellite kSatellites[] = {{"six-digit LEO", 125544}, {"nine-digit LEO", 270033591}, {"six-digit Molniya", 115429}};

const char *kOracle = R"(
import json, math, sys
from sgp4.api import Satrec, jday
from sgp4 import omm
from sgp4.propagation import gstime

csv_path, xml_path, lat, lon, h, start, hours = sys.argv[1:8]
lat, lon, h, start, hours = math.radians(float(lat)), math.radians(float(lon)), float(h) / 1000, float(start), float(hours)

# The catalogue number plays no part in SGP4. python-sgp4's own Python
# propagator (2.22, Debian 13) refuses one past Alpha-5's Z9999 (339999),
# so the oracle is handed 0 for it and keys its answers by the real one.
def read(fields_list):
    sats = {}
    for fields in fields_list:
        s = Satrec()
        omm.initialize(s, dict(fields, NORAD_CAT_ID='0'))
        sats[int(fields['NORAD_CAT_ID'])] = s
    return sats
with open(csv_path) as f:
    from_csv = read(list(omm.parse_csv(f)))
with open(xml_path) as f:
    from_xml = read(list(omm.parse_xml(f)))

# The station on WGS-84, earth-fixed, km.
a, f = 6378.137, 1 / 298.257223563
e2 = f * (2 - f)
n = a / math.sqrt(1 - e2 * math.sin(lat) ** 2)
station = ((n + h) * math.cos(lat) * math.cos(lon), (n + h) * math.cos(lat) * math.sin(lon), (n * (1 - e2) + h) * math.sin(lat))

def look(sat, jd):
    e, r, v = sat.sgp4(math.floor(jd - 0.5) + 0.5, jd - (math.floor(jd - 0.5) + 0.5))
    if e != 0:
        return None
    g = gstime(jd)
    x = r[0] * math.cos(g) + r[1] * math.sin(g)
    y = -r[0] * math.sin(g) + r[1] * math.cos(g)
    d = (x - station[0], y - station[1], r[2] - station[2])
    south = math.sin(lat) * math.cos(lon) * d[0] + math.sin(lat) * math.sin(lon) * d[1] - math.cos(lat) * d[2]
    east = -math.sin(lon) * d[0] + math.cos(lon) * d[1]
    up = math.cos(lat) * math.cos(lon) * d[0] + math.cos(lat) * math.sin(lon) * d[1] + math.sin(lat) * d[2]
    el = math.degrees(math.atan2(up, math.hypot(south, east)))
    az = math.degrees(math.atan2(east, -south)) % 360
    return az, el

def crossing(sat, t0, t1):
    up0 = look(sat, t0)[1] > 0
    while (t1 - t0) * 86400 > 0.001:
        m = (t0 + t1) / 2
        if (look(sat, m)[1] > 0) == up0:
            t0 = m
        else:
            t1 = m
    return (t0 + t1) / 2

out = {'where': {}, 'passes': {}, 'agree': True}
for number, sat in from_csv.items():
    other = from_xml[number]
    w, wx = look(sat, start), look(other, start)
    out['agree'] = out['agree'] and abs(w[0] - wx[0]) < 1e-9 and abs(w[1] - wx[1]) < 1e-9
    out['where'][number] = w
    step, t, passes, aos = 10 / 86400, start, [], None
    was_up = look(sat, t)[1] > 0
    end = start + hours / 24 + 0.5
    while t < end:
        nxt = t + step
        up = look(sat, nxt)[1] > 0
        if up != was_up:
            c = crossing(sat, t, nxt)
            if up:
                aos = c
            elif aos is not None:
                if aos < start + hours / 24:
                    passes.append([aos, c])
                aos = None
        was_up, t = up, nxt
    out['passes'][number] = passes
print(json.dumps(out))
)";

struct Run {
    int exitCode = -1;
    QByteArray out, err;
};

Run runSlew(const QStringList &arguments)
{
    static QTemporaryDir home; // no saved station or sources of the user's
    Run r;
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), home.path());
    env.insert(QStringLiteral("XDG_CACHE_HOME"), home.path());
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
    return QDateTime::fromString(iso, Qt::ISODate).toMSecsSinceEpoch() / 86400000.0 + 2440587.5;
}

double angleBetween(double a, double b)
{
    const double d = std::fmod(std::fabs(a - b), 360.0);
    return std::min(d, 360.0 - d);
}

} // namespace

class TestGpOracle : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void agreesWithPythonSgp4_data();
    void agreesWithPythonSgp4();

private:
    QJsonObject m_oracle;
};

void TestGpOracle::initTestCase()
{
    QVERIFY2(!qEnvironmentVariable("SLEW_BIN").isEmpty(), "SLEW_BIN is not set (tests/CMakeLists.txt sets it)");
    QProcess oracle;
    const QStringList coordinates = kQth.split(u',');
    oracle.start(kPython, {QStringLiteral("-c"), QString::fromLatin1(kOracle), kData + QStringLiteral("gp-2018.csv"),
                           kData + QStringLiteral("gp-2018.xml"), coordinates[0], coordinates[1], coordinates[2],
                           QString::number(kStartJulian, 'f', 6), QString::number(kHours)});
    QVERIFY(oracle.waitForFinished(300000));
    QVERIFY2(oracle.exitCode() == 0, "python3-sgp4 failed (is the Debian package python3-sgp4 installed?): "
                                         + oracle.readAllStandardError());
    m_oracle = QJsonDocument::fromJson(oracle.readAllStandardOutput()).object();
    QVERIFY2(m_oracle.value(QStringLiteral("agree")).toBool(), "python3-sgp4 reads the CSV and the XML differently");
}

void TestGpOracle::agreesWithPythonSgp4_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("number");
    for (const char *file : {"gp-2018.csv", "gp-2018.xml", "gp-2018.json", "gp-2018-spacetrack.json", "gp-2018.kvn",
                             "gp-2018.tle"}) {
        for (const Satellite &s : kSatellites) {
            if (QByteArray(file).endsWith(".tle") && s.number > 339999)
                continue; // no TLE can carry it
            QTest::addRow("%s, %s", file, s.what) << QString::fromLatin1(file) << s.number;
        }
    }
}

void TestGpOracle::agreesWithPythonSgp4()
{
    QFETCH(QString, file);
    QFETCH(int, number);
    const QString path = kData + file;
    const QString key = QString::number(number);

    const Run where = runSlew({QStringLiteral("--where"), key, QStringLiteral("--tle"), path, QStringLiteral("--qth"),
                               kQth, QStringLiteral("--time"), kStart, QStringLiteral("--json")});
    QVERIFY2(where.exitCode == 0, where.err.constData());
    const QJsonObject here = QJsonDocument::fromJson(where.out).object();
    QCOMPARE(here.value(QStringLiteral("catalogue_number")).toInteger(), qint64(number));
    const QJsonArray there = m_oracle.value(QStringLiteral("where")).toObject().value(key).toArray();
    QCOMPARE(there.size(), 2);
    const double dAz = angleBetween(here.value(QStringLiteral("azimuth")).toDouble(), there[0].toDouble());
    const double dEl = std::fabs(here.value(QStringLiteral("elevation")).toDouble() - there[1].toDouble());
    QVERIFY2(dAz < 0.05 && dEl < 0.05, qPrintable(QStringLiteral("az %1 el %2 here, %3 %4 in python3-sgp4")
                                                      .arg(here.value(QStringLiteral("azimuth")).toDouble())
                                                      .arg(here.value(QStringLiteral("elevation")).toDouble())
                                                      .arg(there[0].toDouble())
                                                      .arg(there[1].toDouble())));

    const Run passes = runSlew({QStringLiteral("--passes"), key, QStringLiteral("--tle"), path, QStringLiteral("--qth"),
                                kQth, QStringLiteral("--start"), kStart, QStringLiteral("--hours"), QString::number(kHours),
                                QStringLiteral("--min-el"), QStringLiteral("0"), QStringLiteral("--json")});
    QVERIFY2(passes.exitCode == 0, passes.err.constData());
    qInfo("%s %d: where %.2g° az, %.2g° el from python3-sgp4", qPrintable(file), number, dAz, dEl);
    const QJsonArray ours = QJsonDocument::fromJson(passes.out).array();
    QJsonArray theirs = m_oracle.value(QStringLiteral("passes")).toObject().value(key).toArray();
    // A pass already up at the start is clipped here and not counted there.
    QJsonArray whole;
    for (const QJsonValue &p : ours)
        if (!p.toObject().value(QStringLiteral("aos_clipped")).toBool())
            whole.append(p);
    QVERIFY2(whole.size() >= 1, "no pass to compare");
    QCOMPARE(whole.size(), theirs.size());
    for (qsizetype i = 0; i < whole.size(); ++i) {
        const QJsonObject p = whole[i].toObject();
        const double aos = julianOf(p.value(QStringLiteral("aos")).toObject().value(QStringLiteral("time")).toString());
        const double los = julianOf(p.value(QStringLiteral("los")).toObject().value(QStringLiteral("time")).toString());
        const double dAos = std::fabs(aos - theirs[i].toArray()[0].toDouble()) * 86400.0;
        const double dLos = std::fabs(los - theirs[i].toArray()[1].toDouble()) * 86400.0;
        if (i == 0)
            qInfo("  first of %lld passes: AOS %.3f s, LOS %.3f s from python3-sgp4's", qlonglong(whole.size()), dAos, dLos);
        QVERIFY2(dAos < 2.0 && dLos < 2.0,
                 qPrintable(QStringLiteral("pass %1: AOS %2 s, LOS %3 s from python3-sgp4's").arg(i).arg(dAos).arg(dLos)));
    }
}

QTEST_GUILESS_MAIN(TestGpOracle)
#include "tst_gporacle.moc"
