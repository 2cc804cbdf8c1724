// SPDX-License-Identifier: GPL-3.0-or-later
// Element-set sources: fetched from a small HTTP server on 127.0.0.1 that
// the test runs itself (never the internet), cached on disk, kept when a
// later fetch fails or brings no sets, merged by catalogue number, and
// loaded offline from the cache. Ages are checked against a limit.

#include "../common/tinyhttpserver.h"
#include "sky/tlesources.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace slew::sky;

namespace {

const QByteArray kIss = "ISS (ZARYA)\n"
                        "1 25544U 98067A   08264.51782528 -.00002182  00000-0 -11606-4 0  2927\n"
                        "2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.72125391563537\n";
const QByteArray kNoaa = "NOAA 19\n"
                         "1 33591U 09005A   18020.91958580  .00000107  00000-0  83477-4 0  9992\n"
                         "2 33591  99.1238 356.1693 0014450  24.0615 336.1228 14.12247534461122\n";

bool refreshAndWait(TleSources &sources)
{
    QSignalSpy done(&sources, &TleSources::finished);
    sources.refresh();
    return done.count() > 0 || done.wait(20000);
}

} // namespace

class TestTleSources : public QObject {
    Q_OBJECT
private slots:
    void fetchesCachesAndFallsBack();
    void errorPageDoesNotReplaceTheCache();
    void staleElements();
};

void TestTleSources::fetchesCachesAndFallsBack()
{
    QTemporaryDir cache;
    auto owned = std::make_unique<TinyHttpServer>();
    TinyHttpServer &server = *owned;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    server.pages.insert("/stations.txt", kIss);
    server.pages.insert("/weather.txt", kNoaa + kIss); // the ISS twice, across sources

    TleSources sources(cache.path());
    sources.setUrls({server.url("/stations.txt"), server.url("/weather.txt"), server.url("/missing.txt")});
    QVERIFY(refreshAndWait(sources));
    QCOMPARE(server.requests, 3);
    QList<TleSourceStatus> status = sources.status();
    QVERIFY(status[0].fetched && !status[0].fromCache);
    QCOMPARE(status[1].setCount, 2);
    QVERIFY(!status[2].fetched);
    QVERIFY2(status[2].error.contains(QStringLiteral("Not Found"), Qt::CaseInsensitive), qPrintable(status[2].error));
    QCOMPARE(sources.sets().size(), 2); // merged by catalogue number
    QVERIFY(QFile::exists(sources.cacheFile(server.url("/stations.txt"))));

    // The server goes away, open connections and all: the next refresh
    // keeps the cached copies.
    const QList<QUrl> urls = sources.urls();
    owned.reset();
    QVERIFY(refreshAndWait(sources));
    status = sources.status();
    QVERIFY2(!status[0].fetched && status[0].fromCache,
             qPrintable(QStringLiteral("fetched %1, from cache %2, error '%3', %4 sets")
                            .arg(status[0].fetched)
                            .arg(status[0].fromCache)
                            .arg(status[0].error)
                            .arg(status[0].setCount)));
    QVERIFY(!status[0].error.isEmpty());
    QVERIFY(status[0].cachedAt.isValid());
    QCOMPARE(sources.sets().size(), 2);

    // A new start, offline: everything from the cache, no network at all.
    TleSources offline(cache.path());
    offline.setUrls(urls);
    offline.loadFromCache();
    QCOMPARE(offline.sets().size(), 2);
    QVERIFY(offline.status()[1].fromCache);
    QCOMPARE(offline.status()[2].setCount, 0);
}

void TestTleSources::errorPageDoesNotReplaceTheCache()
{
    QTemporaryDir cache;
    TinyHttpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    server.pages.insert("/amateur.txt", kNoaa);
    TleSources sources(cache.path());
    sources.setUrls({server.url("/amateur.txt")});
    QVERIFY(refreshAndWait(sources));
    QCOMPARE(sources.sets().size(), 1);

    server.pages.insert("/amateur.txt", "<html>rate limited</html>");
    QVERIFY(refreshAndWait(sources));
    QVERIFY(!sources.status()[0].fetched);
    QCOMPARE(sources.status()[0].error, QStringLiteral("the answer holds no element sets"));
    QCOMPARE(sources.sets().size(), 1);
    QCOMPARE(sources.sets()[0].catalogueNumber, 33591);
}

void TestTleSources::staleElements()
{
    const TleReadResult read = readTleText(QString::fromLatin1(kIss + kNoaa));
    QCOMPARE(read.sets.size(), 2);
    // 2018-01-25 00:00 UTC: NOAA 19's set is 4.1 days old, the ISS's 9.3 years.
    const double now = 2458143.5;
    const QList<ElementAge> stale = slew::sky::staleElements(read.sets, now, 3.0);
    QCOMPARE(stale.size(), 2);
    const QList<ElementAge> veryStale = slew::sky::staleElements(read.sets, now, 5.0);
    QCOMPARE(veryStale.size(), 1);
    QCOMPARE(veryStale[0].tle->catalogueNumber, 25544);
    QVERIFY(veryStale[0].ageDays > 3400);

    // A source is as current as its newest set: NOAA 19's.
    QVERIFY(!slew::sky::newestEpochJulian({}).has_value());
    QCOMPARE(slew::sky::newestEpochJulian(read.sets).value(), read.sets[1].epochJulian());
}

QTEST_GUILESS_MAIN(TestTleSources)
#include "tst_tlesources.moc"
