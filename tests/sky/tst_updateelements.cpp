// SPDX-License-Identifier: GPL-3.0-or-later
// `slew --update-elements` as the real program, against a web server the
// test runs on 127.0.0.1: one line per source, exit status 1 naming each
// source that failed, the cache written where the window reads it, the
// window's saved sources refreshed when no URL is given, and a one-set page
// refused against a full cache. HOME and the XDG directories point into a
// temporary directory, never the user's own.

#include "../common/tinyhttpserver.h"
#include "sky/elementsetsources.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace slew::sky;

namespace {

const QString kFullGroup = QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle");
const QByteArray kNoaa = "NOAA 19\n"
                         "1 33591U 09005A   18020.91958580  .00000107  00000-0  83477-4 0  9992\n"
                         "2 33591  99.1238 356.1693 0014450  24.0615 336.1228 14.12247534461122\n";

QByteArray fileBytes(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

struct Run {
    int exitCode = -1;
    QStringList lines; // standard output
    QString err;
};

// A home of the test's own, as a user's would be laid out.
struct Home {
    QTemporaryDir dir;
    QString cache() const { return dir.filePath(QStringLiteral("cache")); }
    QString config() const { return dir.filePath(QStringLiteral("config")); }
    // Where the window keeps its cached copies, with these XDG directories.
    QString windowCacheDirectory() const { return cache() + QStringLiteral("/Slew/slew/element-sets"); }
    // The window's list of sources, as Sky → Element sets… saves it.
    void saveSources(const QList<QUrl> &urls) const
    {
        QStringList texts;
        for (const QUrl &url : urls)
            texts << url.toString();
        QSettings settings(config() + QStringLiteral("/Slew/slew.conf"), QSettings::IniFormat);
        settings.setValue(QLatin1String(kElementSetUrlsSettingsKey), texts);
    }
};

// Runs slew and waits on its finished signal: the event loop keeps running,
// so the test's own server answers meanwhile.
Run runSlew(const Home &home, const QStringList &arguments)
{
    Run r;
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("HOME"), home.dir.path());
    env.insert(QStringLiteral("XDG_CACHE_HOME"), home.cache());
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), home.config());
    env.remove(QStringLiteral("QT_QPA_PLATFORM")); // no window, so no platform is needed
    p.setProcessEnvironment(env);
    QSignalSpy finished(&p, &QProcess::finished);
    p.start(qEnvironmentVariable("SLEW_BIN"), arguments);
    if (!finished.wait(60000)) {
        p.kill();
        return r;
    }
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
    r.lines = QString::fromUtf8(p.readAllStandardOutput()).split(u'\n', Qt::SkipEmptyParts);
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

} // namespace

class TestUpdateElements : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY2(!qEnvironmentVariable("SLEW_BIN").isEmpty(), "SLEW_BIN is not set (tests/CMakeLists.txt sets it)");
    }

    void refreshesEachSourceAndNamesTheFailures()
    {
        Home home;
        TinyHttpServer server;
        QVERIFY(server.listen(QHostAddress::LocalHost, 0));
        const QByteArray full = fileBytes(kFullGroup);
        server.pages.insert("/amateur.txt", full);
        const QUrl good = server.url("/amateur.txt"), missing = server.url("/missing.txt");

        const Run run = runSlew(home, {QStringLiteral("--update-elements"), good.toString(), missing.toString()});
        QCOMPARE(run.exitCode, 1);
        QCOMPARE(run.lines.size(), 2);
        QCOMPARE(run.lines[0], good.toString() + QStringLiteral(": replaced, 979 sets"));
        QCOMPARE(run.lines[1],
                 missing.toString() + QStringLiteral(": failed, no cached copy: the server answered 404 Not Found"));
        QVERIFY2(run.err.contains(QStringLiteral("1 of 2 sources not refreshed: ") + missing.toString()),
                 qPrintable(run.err));
        QVERIFY(!run.err.contains(good.toString()));
        // Where the window reads it.
        QCOMPARE(fileBytes(elementSetCacheFile(home.windowCacheDirectory(), good)), full);
        QVERIFY(!QFile::exists(elementSetCacheFile(home.windowCacheDirectory(), missing)));
    }

    void refreshesTheWindowsSourcesAndKeepsAFullCopy()
    {
        Home home;
        TinyHttpServer server;
        QVERIFY(server.listen(QHostAddress::LocalHost, 0));
        const QByteArray full = fileBytes(kFullGroup);
        server.pages.insert("/amateur.txt", full);
        server.pages.insert("/weather.txt", kNoaa);
        const QUrl amateur = server.url("/amateur.txt"), weather = server.url("/weather.txt");
        home.saveSources({amateur, weather});

        Run run = runSlew(home, {QStringLiteral("--update-elements")});
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(run.lines, (QStringList{amateur.toString() + QStringLiteral(": replaced, 979 sets"),
                                         weather.toString() + QStringLiteral(": replaced, 1 set")}));
        QVERIFY2(run.err.isEmpty(), qPrintable(run.err));
        QCOMPARE(server.requests, 2);

        // A portal's page with one set: the full copy stays, and says why.
        server.pages.insert("/amateur.txt", "<html><body><pre>\n" + kNoaa + "</pre></body></html>\n");
        run = runSlew(home, {QStringLiteral("--update-elements")});
        QCOMPARE(run.exitCode, 1);
        QCOMPARE(run.lines.size(), 2);
        QVERIFY2(run.lines[0].startsWith(amateur.toString() + QStringLiteral(": kept the cached copy (979 sets from "))
                     && run.lines[0].contains(QStringLiteral("the answer is an HTML page")),
                 qPrintable(run.lines[0]));
        QCOMPARE(run.lines[1], weather.toString() + QStringLiteral(": replaced, 1 set"));
        QVERIFY2(run.err.contains(amateur.toString()) && !run.err.contains(weather.toString()), qPrintable(run.err));
        QCOMPARE(fileBytes(elementSetCacheFile(home.windowCacheDirectory(), amateur)), full);
    }

    // CelesTrak's GP queries, the only way to the satellites with six-digit
    // numbers: the answer (CSV, JSON) fills the cache, the URLs join the
    // window's sources, and --where, --passes and --export-elements then
    // read the cache with no --tle, saying so.
    void gpQueriesFillTheCacheThatTheCommandLineReads()
    {
        Home home;
        TinyHttpServer server;
        QVERIFY(server.listen(QHostAddress::LocalHost, 0));
        const QString gp = QStringLiteral(SLEW_TEST_DATA_DIR "/gp/");
        server.pages.insert("/NORAD/elements/gp.php?GROUP=amateur&FORMAT=csv", fileBytes(gp + QStringLiteral("gp-2018.csv")));
        server.pages.insert("/NORAD/elements/supplemental/sup-gp.php?FILE=test&FORMAT=json",
                            fileBytes(gp + QStringLiteral("gp-2018-spacetrack.json")));
        const QUrl csv = server.url("/NORAD/elements/gp.php?GROUP=amateur&FORMAT=csv");
        const QUrl json = server.url("/NORAD/elements/supplemental/sup-gp.php?FILE=test&FORMAT=json");

        Run run = runSlew(home, {QStringLiteral("--update-elements"), csv.toString(), json.toString()});
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(run.lines, (QStringList{csv.toString() + QStringLiteral(": replaced, 5 sets"),
                                         json.toString() + QStringLiteral(": replaced, 5 sets")}));

        const QStringList station = {QStringLiteral("--qth"), QStringLiteral("JO65hq"), QStringLiteral("--time"),
                                     QStringLiteral("2018-01-21T00:00:00Z")};
        run = runSlew(home, QStringList{QStringLiteral("--where"), QStringLiteral("270033591"), QStringLiteral("--json")}
                                + station);
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        QVERIFY2(run.lines.join(u'\n').contains(QStringLiteral("\"catalogue_number\": 270033591")),
                 qPrintable(run.lines.join(u'\n')));
        QVERIFY2(run.err.contains(QStringLiteral("element sets from the cached copies of 2 sources")), qPrintable(run.err));
        QVERIFY2(run.err.contains(csv.toString() + QStringLiteral(": 5 sets (CSV), downloaded ")), qPrintable(run.err));

        run = runSlew(home, QStringList{QStringLiteral("--where"), QStringLiteral("GP TEST HEO-6")} + station);
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        QVERIFY2(run.lines.value(0).startsWith(QStringLiteral("GP TEST HEO-6 (MOLNIYA 1-63 ELEMENTS) at ")),
                 qPrintable(run.lines.value(0)));

        run = runSlew(home, {QStringLiteral("--passes"), QStringLiteral("C5544"), QStringLiteral("--qth"),
                             QStringLiteral("JO65hq"), QStringLiteral("--start"), QStringLiteral("2018-01-21T00:00:00Z"),
                             QStringLiteral("--json")});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        QVERIFY2(run.lines.join(u'\n').contains(QStringLiteral("\"catalogue_number\": 125544")), qPrintable(run.err));

        // For a program that reads TLEs only: Alpha-5, and the one a TLE
        // cannot carry named.
        run = runSlew(home, {QStringLiteral("--export-elements"), QStringLiteral("--format"), QStringLiteral("tle")});
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(run.lines.size(), 12);
        QVERIFY(run.lines.contains(QStringLiteral("2 C5544  51.6424  32.9776 0003646  28.7227  39.5332 15.54190080 95612")));
        QVERIFY2(run.err.contains(QStringLiteral("not written as TLE: GP TEST LEO-9 (NOAA 19 ELEMENTS) (270033591): "
                                                 "catalogue number 270033591 is above 339999")),
                 qPrintable(run.err));
        QVERIFY2(run.err.contains(QStringLiteral("4 of 5 sets written as TLE")), qPrintable(run.err));

        run = runSlew(home, {QStringLiteral("--export-elements"), QStringLiteral("--format"), QStringLiteral("csv"),
                             QStringLiteral("270033591"), QStringLiteral("FO-29")});
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(run.lines.size(), 3);
        QVERIFY(run.lines[1].contains(QStringLiteral(",270033591,")));
        run = runSlew(home, {QStringLiteral("--export-elements"), QStringLiteral("--format"), QStringLiteral("yaml")});
        QCOMPARE(run.exitCode, 2);
        run = runSlew(home, {QStringLiteral("--export-elements"), QStringLiteral("GP TEST")});
        QCOMPARE(run.exitCode, 1);
        QVERIFY2(run.err.contains(QStringLiteral("'GP TEST' matches 4 satellites")), qPrintable(run.err));
    }

    void noSourcesIsABadArgument()
    {
        Home home;
        const Run run = runSlew(home, {QStringLiteral("--update-elements")});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("no sources")), qPrintable(run.err));
        const Run bad = runSlew(home, {QStringLiteral("--update-elements"), QStringLiteral("celestrak dot org")});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY2(bad.err.contains(QStringLiteral("not an http, https or file URL")), qPrintable(bad.err));
    }

    void helpDescribesIt()
    {
        Home home;
        const Run help = runSlew(home, {QStringLiteral("--help")});
        QCOMPARE(help.exitCode, 0);
        QVERIFY2(help.lines.join(u'\n').contains(QStringLiteral("slew --update-elements")), qPrintable(help.lines.join(u'\n')));
        const Run own = runSlew(home, {QStringLiteral("--update-elements"), QStringLiteral("--help")});
        QCOMPARE(own.exitCode, 0);
        QVERIFY(own.lines.join(u'\n').contains(QStringLiteral("larger than 32 MiB")));
    }
};

QTEST_GUILESS_MAIN(TestUpdateElements)
#include "tst_updateelements.moc"
