// SPDX-License-Identifier: GPL-3.0-or-later
// Transponder sources, cached beside the element sets: SatNOGS DB's list
// over HTTP from a server the test runs on 127.0.0.1 and Gpredict .trsp
// files by file URL; a new copy taken and cached atomically, a bad one (an
// HTML page, a list cut to one satellite, one over the cap, a server gone
// silent) refused with the cached copy kept. Then `slew
// --update-transponders` as the real program, and the station service
// tuning from what it cached. HOME and the XDG directories point into a
// temporary directory, never the user's own.

#include "../common/tinyhttpserver.h"
#include "radio/transponderimport.h"
#include "radio/transpondersources.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <sys/stat.h>

using namespace slew::radio;

namespace {

const QString kData = QStringLiteral(SLEW_TEST_DATA_DIR "/transponders/");

QByteArray fileBytes(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// One refresh, waited for on its signal.
bool refreshed(TransponderSources &sources)
{
    QSignalSpy finished(&sources, &TransponderSources::finished);
    sources.refresh();
    return finished.wait(20000);
}

struct Home {
    QTemporaryDir dir;
    QString cache() const { return dir.filePath(QStringLiteral("cache")); }
    QString config() const { return dir.filePath(QStringLiteral("config")); }
    QProcessEnvironment environment() const
    {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("HOME"), dir.path());
        env.insert(QStringLiteral("XDG_CACHE_HOME"), cache());
        env.insert(QStringLiteral("XDG_CONFIG_HOME"), config());
        env.remove(QStringLiteral("QT_QPA_PLATFORM"));
        env.remove(QStringLiteral("DISPLAY"));
        return env;
    }
};

} // namespace

class TransponderSourcesTest : public QObject {
    Q_OBJECT
private slots:
    void takesAGoodCopyAndKeepsItAgainstBadOnes()
    {
        QTemporaryDir cache;
        TinyHttpServer server;
        QVERIFY(server.listen(QHostAddress::LocalHost, 0));
        const QByteArray list = fileBytes(kData + "satnogs-transmitters.json");
        QVERIFY(!list.isEmpty());
        server.pages.insert("/transmitters", list);
        const QUrl url = server.url("/transmitters");

        TransponderSources sources(cache.path());
        sources.setUrls({url});
        QVERIFY(refreshed(sources));
        QVERIFY2(sources.status().at(0).fetched && sources.status().at(0).error.isEmpty(),
                 qPrintable(describeTransponderSource(sources.status().at(0))));
        const int count = sources.transponders().size();
        QVERIFY(count > 3);
        QCOMPARE(fileBytes(sources.cacheFile(url)), list);

        // A login page, an empty list, a list of one other satellite:
        // each refused, the good copy kept and still used.
        const QList<QByteArray> bad{"<html><body>Log in</body></html>", "[]",
                                    R"([{"uuid":"x","description":"beacon","alive":true,"uplink_low":null,)"
                                    R"("uplink_high":null,"downlink_low":437000000,"downlink_high":null,"mode":"CW",)"
                                    R"("invert":false,"norad_cat_id":99999}])"};
        for (const QByteArray &page : bad) {
            server.pages.insert("/transmitters", page);
            QVERIFY(refreshed(sources));
            const TransponderSourceStatus s = sources.status().at(0);
            QVERIFY2(!s.fetched && s.fromCache && !s.error.isEmpty(), qPrintable(describeTransponderSource(s)));
            QCOMPARE(sources.transponders().size(), count);
            QCOMPARE(fileBytes(sources.cacheFile(url)), list);
        }

        // A fresh object, as the next start: the cached copy, no network.
        server.close();
        TransponderSources later(cache.path());
        later.setUrls({url});
        QSignalSpy loaded(&later, &TransponderSources::loaded);
        later.loadFromCache();
        QVERIFY(loaded.wait(10000));
        QCOMPARE(later.transponders().size(), count);
        QVERIFY(later.status().at(0).fromCache);
    }

    void aServerThatSendsTooMuchOrNothingIsGivenUp()
    {
        QTemporaryDir cache;
        TinyHttpServer server;
        QVERIFY(server.listen(QHostAddress::LocalHost, 0));
        TinyHttpAnswer huge;
        huge.body = "[";
        huge.generatedBytes = kLargestTransmitterList + 1024;
        server.answers.insert("/huge", huge);
        TinyHttpAnswer silent;
        silent.silentAfterHeaders = true;
        silent.announcedLength = 100000; // and then not a byte of it
        server.answers.insert("/silent", silent);
        TransponderSources sources(cache.path());
        sources.setSilenceLimitMs(500);
        sources.setUrls({server.url("/huge"), server.url("/silent")});
        QVERIFY(refreshed(sources));
        QVERIFY2(sources.status().at(0).error.contains("larger than"), qPrintable(sources.status().at(0).error));
        QVERIFY2(sources.status().at(1).error.contains("no data for"), qPrintable(sources.status().at(1).error));
        QVERIFY(sources.transponders().isEmpty());
        QVERIFY(!QFileInfo::exists(sources.cacheFile(server.url("/huge"))));
    }

    void aTrspFileKeepsItsSatellitesNumber()
    {
        QTemporaryDir cache;
        const QUrl trsp = QUrl::fromLocalFile(kData + "24278.trsp");
        TransponderSources sources(cache.path());
        sources.setUrls({trsp});
        QVERIFY(refreshed(sources));
        QVERIFY2(sources.status().at(0).fetched, qPrintable(describeTransponderSource(sources.status().at(0))));
        QVERIFY(!sources.transponders().forSatellite(24278).isEmpty());
        QCOMPARE(QFileInfo(sources.cacheFile(trsp)).fileName(), QString("24278.trsp"));
        // The cached copy reads back as the same satellite's.
        const TransponderImport again = readGpredictTrspFile(sources.cacheFile(trsp));
        QVERIFY2(again.ok(), qPrintable(again.error));
        QCOMPARE(again.transponders.size(), sources.transponders().forSatellite(24278).size());
        // A FIFO named as a source is refused without blocking.
        const QString fifo = cache.filePath("fifo.trsp");
        QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
        sources.setUrls({QUrl::fromLocalFile(fifo)});
        QVERIFY(refreshed(sources));
        QVERIFY(!sources.status().at(0).error.isEmpty());
    }

    void theProgramRefreshesAndTheServiceTunesFromTheCache()
    {
        Home home;
        TinyHttpServer server;
        QVERIFY(server.listen(QHostAddress::LocalHost, 0));
        server.pages.insert("/transmitters", fileBytes(kData + "satnogs-transmitters.json"));
        const QUrl url = server.url("/transmitters");
        QProcess p;
        p.setProcessEnvironment(home.environment());
        QSignalSpy finished(&p, &QProcess::finished);
        p.start(qEnvironmentVariable("SLEW_BIN"), {"--update-transponders", url.toString()});
        QVERIFY(finished.wait(30000));
        const QByteArray out = p.readAllStandardOutput();
        QVERIFY2(p.exitCode() == 0, (out + p.readAllStandardError()).constData());
        QVERIFY2(out.contains(url.toString().toUtf8() + ": replaced, "), out.constData());
        // Kept as the sources: a second run with no URL refreshes the same one.
        server.close();
        QProcess again;
        again.setProcessEnvironment(home.environment());
        QSignalSpy againFinished(&again, &QProcess::finished);
        again.start(qEnvironmentVariable("SLEW_BIN"), {"--update-transponders"});
        QVERIFY(againFinished.wait(30000));
        QCOMPARE(again.exitCode(), 1); // the server is gone: not refreshed, and said
        QVERIFY(again.readAllStandardOutput().contains("kept the cached copy"));

        // The service, given a radio and no frequencies, takes the
        // satellite's default transponder from the cache: the ISS (25544)
        // is in the sample list.
        QProcess slew;
        slew.setProcessEnvironment(home.environment());
        slew.start(qEnvironmentVariable("SLEW_BIN"),
                   {"--headless", "--connect", "sim:", "--qth", "JO65hq", "--tle", SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle",
                    "--track", "25544", "--clock-start", "2018-01-22T07:00:00Z",
                    "--radio", "rigctld://127.0.0.1:1"});
        QByteArray log;
        QVERIFY2(QTest::qWaitFor(
                     [&] {
                         log += slew.readAllStandardOutput();
                         return log.contains("radio: connecting to") || slew.state() == QProcess::NotRunning;
                     },
                     20000),
                 (log + slew.readAllStandardError()).constData());
        QVERIFY2(log.contains("radio: connecting to rigctld://127.0.0.1:1"), (log + slew.readAllStandardError()).constData());
        QSignalSpy slewFinished(&slew, &QProcess::finished);
        slew.terminate();
        QVERIFY(slewFinished.wait(10000));
    }
};

QTEST_GUILESS_MAIN(TransponderSourcesTest)
#include "tst_transpondersources.moc"
