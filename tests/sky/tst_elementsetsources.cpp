// SPDX-License-Identifier: GPL-3.0-or-later
// Element-set sources: fetched from a small HTTP server on 127.0.0.1 that
// the test runs itself (never the internet), cached on disk, kept when a
// later fetch fails or brings no sets, merged by catalogue number, and
// loaded offline from the cache. Ages are checked against a limit.
//
// And the answers a careless or hostile server gives: too large (announced,
// chunked or delimited by the close), dripping, silent, an HTML page with
// one set, a transfer cut short; a FIFO or a device as a file:// source or
// as the cache. Each is given up with a message saying what happened, the
// good copy stays, memory stays bounded and the event loop keeps running.

#include "../common/tinyhttpserver.h"
#include "sky/tleformat.h"
#include "sky/elementsetcheck.h"
#include "sky/elementsetsources.h"

#include <QElapsedTimer>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <memory>
#include <sys/stat.h>

using namespace slew::sky;

namespace {

const QByteArray kIss = "ISS (ZARYA)\n"
                        "1 25544U 98067A   08264.51782528 -.00002182  00000-0 -11606-4 0  2927\n"
                        "2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.72125391563537\n";
const QByteArray kNoaa = "NOAA 19\n"
                         "1 33591U 09005A   18020.91958580  .00000107  00000-0  83477-4 0  9992\n"
                         "2 33591  99.1238 356.1693 0014450  24.0615 336.1228 14.12247534461122\n";
// 979 real sets: a full group file.
const QString kFullGroup = QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle");

QByteArray fileBytes(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

char checksum(const QByteArray &line)
{
    int sum = 0;
    for (char c : line.left(68))
        sum += (c >= '0' && c <= '9') ? c - '0' : (c == '-' ? 1 : 0);
    return char('0' + sum % 10);
}

// `count` distinct sets (the ISS's elements under catalogue numbers from 1):
// a group file as large as wanted.
QByteArray manySets(int count)
{
    QByteArray text;
    QByteArray line1 = "1 25544U 98067A   08264.51782528 -.00002182  00000-0 -11606-4 0  2927";
    QByteArray line2 = "2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.72125391563537";
    text.reserve(qsizetype(count) * 160);
    for (int n = 1; n <= count; ++n) {
        const QByteArray number = QByteArray::number(n).rightJustified(5, '0');
        line1.replace(2, 5, number);
        line2.replace(2, 5, number);
        line1[68] = checksum(line1);
        line2[68] = checksum(line2);
        text += "SAT " + QByteArray::number(n) + '\n' + line1 + '\n' + line2 + '\n';
    }
    return text;
}

bool refreshAndWait(ElementSetSources &sources, int timeoutMs = 20000)
{
    QSignalSpy done(&sources, &ElementSetSources::finished);
    sources.refresh();
    return done.count() > 0 || done.wait(timeoutMs);
}

bool loadAndWait(ElementSetSources &sources)
{
    QSignalSpy done(&sources, &ElementSetSources::loaded);
    sources.loadFromCache();
    return done.count() > 0 || done.wait(20000);
}

// The process's peak resident memory in KiB since resetPeakMemory().
qint64 peakMemoryKiB()
{
    QFile status(QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray &line : status.readAll().split('\n'))
        if (line.startsWith("VmHWM:"))
            return line.mid(6).trimmed().split(' ').value(0).toLongLong();
    return -1;
}

// Reading up to the cap takes 32 MiB and a copy: 66 MB measured. The whole
// answer would take several hundred. The address sanitizer keeps freed
// memory in quarantine, so its bound is looser. (The test's own code is
// not instrumented in the sanitizer build, so the runtime is asked for:
// its entry point is there only when it is linked in.)
extern "C" void __asan_init() __attribute__((weak));
qint64 peakGrowthLimitKiB()
{
    return &__asan_init != nullptr ? 400 * 1024 : 120 * 1024;
}

bool resetPeakMemory()
{
    QFile clear(QStringLiteral("/proc/self/clear_refs"));
    return clear.open(QIODevice::WriteOnly) && clear.write("5") == 1;
}

QString describe(const ElementSetSourceStatus &s)
{
    return describeSource(s);
}

// A source whose cache already holds the full 979-set group, fetched from a
// server on 127.0.0.1 that a test then makes answer badly.
struct FullCache {
    QTemporaryDir cache;
    TinyHttpServer server;
    QByteArray full = fileBytes(kFullGroup);
    ElementSetSources sources{cache.path()};
    QString cacheFile;

    bool fill()
    {
        if (!server.listen(QHostAddress::LocalHost, 0))
            return false;
        server.pages.insert("/amateur.txt", full);
        sources.setUrls({server.url("/amateur.txt")});
        if (!refreshAndWait(sources) || sources.status()[0].setCount != 979)
            return false;
        cacheFile = sources.cacheFile(server.url("/amateur.txt"));
        return fileBytes(cacheFile) == full;
    }
};

} // namespace

class TestElementSetSources : public QObject {
    Q_OBJECT
private slots:
    void fetchesCachesAndFallsBack();
    void errorPageDoesNotReplaceTheCache();
    void staleElements();
    void plausibility();
    void answerLargerThanTheCapIsGivenUp_data();
    void answerLargerThanTheCapIsGivenUp();
    void slowDripIsGivenUpAtTheTransferLimit();
    void silenceIsGivenUpAndSaysSo();
    void oneSetPageDoesNotReplaceAFullCache();
    void cutOffAnswerDoesNotReplaceAFullCache();
    void fifoAndDeviceAsSourcesAreRefused();
    void fifoAsCacheIsRefusedAtLoad();
    void parsingLeavesTheEventLoopFree();
};

void TestElementSetSources::fetchesCachesAndFallsBack()
{
    QTemporaryDir cache;
    auto owned = std::make_unique<TinyHttpServer>();
    TinyHttpServer &server = *owned;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    server.pages.insert("/stations.txt", kIss);
    server.pages.insert("/weather.txt", kNoaa + kIss); // the ISS twice, across sources

    ElementSetSources sources(cache.path());
    sources.setUrls({server.url("/stations.txt"), server.url("/weather.txt"), server.url("/missing.txt")});
    QVERIFY(refreshAndWait(sources));
    QCOMPARE(server.requests, 3);
    QList<ElementSetSourceStatus> status = sources.status();
    QVERIFY(status[0].fetched && !status[0].fromCache);
    QCOMPARE(status[1].setCount, 2);
    QVERIFY(!status[2].fetched);
    QVERIFY2(status[2].error.contains(QStringLiteral("404 Not Found")), qPrintable(status[2].error));
    QCOMPARE(sources.sets().size(), 2); // merged by catalogue number
    QVERIFY(QFile::exists(sources.cacheFile(server.url("/stations.txt"))));

    // The server goes away, open connections and all: the next refresh
    // keeps the cached copies.
    const QList<QUrl> urls = sources.urls();
    owned.reset();
    QVERIFY(refreshAndWait(sources));
    status = sources.status();
    QVERIFY2(!status[0].fetched && status[0].fromCache, qPrintable(describe(status[0])));
    QVERIFY(!status[0].error.isEmpty());
    QVERIFY(status[0].cachedAt.isValid());
    QCOMPARE(sources.sets().size(), 2);

    // A new start, offline: everything from the cache, no network at all,
    // read off the event loop and announced by loaded().
    ElementSetSources offline(cache.path());
    offline.setUrls(urls);
    QVERIFY(loadAndWait(offline));
    QCOMPARE(offline.sets().size(), 2);
    QVERIFY(offline.status()[1].fromCache);
    QCOMPARE(offline.status()[2].setCount, 0);
}

void TestElementSetSources::errorPageDoesNotReplaceTheCache()
{
    QTemporaryDir cache;
    TinyHttpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    server.pages.insert("/amateur.txt", kNoaa);
    ElementSetSources sources(cache.path());
    sources.setUrls({server.url("/amateur.txt")});
    QVERIFY(refreshAndWait(sources));
    QCOMPARE(sources.sets().size(), 1);

    server.pages.insert("/amateur.txt", "<html>rate limited</html>");
    QVERIFY(refreshAndWait(sources));
    QVERIFY(!sources.status()[0].fetched);
    QCOMPARE(sources.status()[0].error, QStringLiteral("the answer is an HTML page, not an element-set file"));
    QCOMPARE(sources.sets().size(), 1);
    QCOMPARE(sources.sets()[0].catalogueNumber, 33591);
}

void TestElementSetSources::staleElements()
{
    const ElementSetRead read = readTleText(QString::fromLatin1(kIss + kNoaa));
    QCOMPARE(read.sets.size(), 2);
    // 2018-01-25 00:00 UTC: NOAA 19's set is 4.1 days old, the ISS's 9.3 years.
    const double now = 2458143.5;
    const QList<ElementAge> stale = slew::sky::staleElements(read.sets, now, 3.0);
    QCOMPARE(stale.size(), 2);
    const QList<ElementAge> veryStale = slew::sky::staleElements(read.sets, now, 5.0);
    QCOMPARE(veryStale.size(), 1);
    QCOMPARE(veryStale[0].set->catalogueNumber, 25544);
    QVERIFY(veryStale[0].ageDays > 3400);
    // Either side of the epoch: elements asked about a time long before it
    // predict as badly.
    QCOMPARE(slew::sky::staleElements(read.sets, read.sets[1].epochJulian() - 4.0, 3.0).size(), 2);

    // The reason, as the schedule and the trackers give it.
    QVERIFY(slew::sky::elementsTooOld(read.sets[1], now, 5.0, QStringLiteral("AOS")).isEmpty());
    const QString why = slew::sky::elementsTooOld(read.sets[1], now, 3.0, QStringLiteral("AOS"));
    QVERIFY2(why.startsWith(QStringLiteral("its elements are 4.1 days from AOS (epoch 2018-01-20T")), qPrintable(why));
    QVERIFY2(why.endsWith(QStringLiteral("; the limit is 3 days")), qPrintable(why));
    const QString halfDay = slew::sky::elementsTooOld(read.sets[1], now, 0.5, QStringLiteral("now"));
    QVERIFY2(halfDay.contains(QStringLiteral(" days from now (epoch 2018-01-20T"))
                 && halfDay.endsWith(QStringLiteral("; the limit is 0.5 days")),
             qPrintable(halfDay));

    // A source is as current as its newest set: NOAA 19's.
    QVERIFY(!slew::sky::newestEpochJulian({}).has_value());
    QCOMPARE(slew::sky::newestEpochJulian(read.sets).value(), read.sets[1].epochJulian());
}

void TestElementSetSources::plausibility()
{
    const auto read = [](const QByteArray &text) { return readTleText(QString::fromLatin1(text)); };
    const QByteArray twenty = manySets(20);
    // A clean copy with no old one, and one that keeps what the old one had.
    QVERIFY(whyNotReplace(twenty, read(twenty), {}).isEmpty());
    QVERIFY(whyNotReplace(twenty, read(twenty), read(manySets(30)).sets).isEmpty()); // 20 of 30 stay
    // Fewer than half of the old satellites: refused, with the counts.
    const QString lost = whyNotReplace(twenty, read(twenty), read(manySets(50)).sets);
    QVERIFY2(lost.contains(QStringLiteral("keeps 20 of the 50 satellites")), qPrintable(lost));
    // One stray line is allowed; more than one in ten is not.
    const QByteArray oneStray = kNoaa + "1 broken\n";
    QVERIFY(whyNotReplace(oneStray, read(oneStray), {}).isEmpty());
    const QByteArray strays = twenty + "junk one\njunk two\njunk three\n";
    const QString unclean = whyNotReplace(strays, read(strays), {});
    QVERIFY2(unclean.contains(QStringLiteral("does not read cleanly")), qPrintable(unclean));
    // An HTML page with a set inside, even with no old copy.
    const QByteArray page = "<!DOCTYPE html>\n<html><body><pre>\n" + kIss + "</pre></body></html>\n";
    const QString html = whyNotReplace(page, read(page), {});
    QVERIFY2(html.contains(QStringLiteral("HTML page")), qPrintable(html));
}

void TestElementSetSources::answerLargerThanTheCapIsGivenUp_data()
{
    QTest::addColumn<int>("length");
    QTest::newRow("Content-Length") << int(TinyHttpAnswer::Length::Announced);
    QTest::newRow("chunked") << int(TinyHttpAnswer::Length::Chunked);
    QTest::newRow("until the close") << int(TinyHttpAnswer::Length::UntilClose);
}

void TestElementSetSources::answerLargerThanTheCapIsGivenUp()
{
    QFETCH(int, length);
    QTemporaryDir cache;
    TinyHttpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    server.pages.insert("/active.txt", kIss);
    ElementSetSources sources(cache.path());
    sources.setUrls({server.url("/active.txt")});
    QVERIFY(refreshAndWait(sources));
    const QByteArray cached = fileBytes(sources.cacheFile(server.url("/active.txt")));
    QCOMPARE(cached, kIss);

    // 100 MB of valid sets, made by the server as it sends them.
    TinyHttpAnswer huge;
    huge.body = kNoaa;
    huge.generatedBytes = 100 * 1000 * 1000;
    huge.length = TinyHttpAnswer::Length(length);
    server.answers.insert("/active.txt", huge);
    const bool peakKnown = resetPeakMemory();
    const qint64 peakBefore = peakMemoryKiB();
    QElapsedTimer clock;
    clock.start();
    QVERIFY(refreshAndWait(sources));
    const qint64 grewKiB = peakMemoryKiB() - peakBefore;
    qInfo("given up after %lld ms, %lld bytes sent by the server, peak memory grew by %lld KiB%s",
          qlonglong(clock.elapsed()), qlonglong(server.bytesSent), qlonglong(grewKiB),
          peakKnown ? "" : " (peak not resettable: since the start)");

    const ElementSetSourceStatus s = sources.status()[0];
    QVERIFY2(s.error.contains(QStringLiteral("larger than the 32 MiB limit")), qPrintable(describe(s)));
    QVERIFY(!s.error.contains(QStringLiteral("cancel"), Qt::CaseInsensitive));
    QVERIFY(!s.fetched && s.fromCache);
    QCOMPARE(sources.sets().size(), 1);
    QCOMPARE(fileBytes(sources.cacheFile(server.url("/active.txt"))), cached);
    QVERIFY(describe(s).startsWith(server.url("/active.txt").toString()));
    // Read no further than the cap (and what was in flight), and memory
    // stays near it: far from the 100 MB the server offered.
    QVERIFY2(server.bytesSent < 50 * 1000 * 1000, qPrintable(QString::number(server.bytesSent)));
    if (peakKnown)
        QVERIFY2(grewKiB < peakGrowthLimitKiB(), qPrintable(QStringLiteral("peak grew by %1 KiB").arg(grewKiB)));
}

void TestElementSetSources::slowDripIsGivenUpAtTheTransferLimit()
{
    QTemporaryDir cache;
    TinyHttpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    server.pages.insert("/drip.txt", kIss);
    ElementSetSources sources(cache.path());
    sources.setUrls({server.url("/drip.txt")});
    QVERIFY(refreshAndWait(sources));

    // One byte every 200 ms never trips the silence limit; the whole
    // transfer's limit (1 s here, 120 s by default) ends it.
    TinyHttpAnswer drip;
    drip.body = kNoaa;
    drip.dripMs = 200;
    server.answers.insert("/drip.txt", drip);
    sources.setTransferLimitMs(1000);
    QElapsedTimer clock;
    clock.start();
    QVERIFY(refreshAndWait(sources, 10000));
    qInfo("the drip was given up after %lld ms", qlonglong(clock.elapsed()));
    QVERIFY(clock.elapsed() < 5000);
    const ElementSetSourceStatus s = sources.status()[0];
    QCOMPARE(s.error, QStringLiteral("took longer than 1 s"));
    QVERIFY(s.fromCache);
    QCOMPARE(sources.sets().size(), 1);
    QCOMPARE(sources.sets()[0].catalogueNumber, 25544);
    QVERIFY(!sources.isRefreshing()); // Refresh is offered again
}

void TestElementSetSources::silenceIsGivenUpAndSaysSo()
{
    QTemporaryDir cache;
    TinyHttpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    TinyHttpAnswer silent;
    silent.body = kIss;
    silent.silentAfterHeaders = true;
    server.answers.insert("/silent.txt", silent);
    ElementSetSources sources(cache.path());
    sources.setUrls({server.url("/silent.txt")});
    sources.setSilenceLimitMs(300);
    QVERIFY(refreshAndWait(sources, 10000));
    const ElementSetSourceStatus s = sources.status()[0];
    QCOMPARE(s.error, QStringLiteral("no data for 300 ms"));
    QVERIFY(!s.fetched && !s.fromCache);
    QVERIFY2(describe(s).contains(QStringLiteral("failed, no cached copy")), qPrintable(describe(s)));
}

void TestElementSetSources::oneSetPageDoesNotReplaceAFullCache()
{
    FullCache f;
    QVERIFY(f.fill());
    TinyHttpServer &server = f.server;
    ElementSetSources &sources = f.sources;
    const QByteArray &full = f.full;
    const QString &cacheFile = f.cacheFile;

    // A portal's page with one example set in it.
    server.pages.insert("/amateur.txt", "<!DOCTYPE html>\n<html>\n<head><title>Maintenance</title></head>\n<body>\n"
                                        "<p>Back soon. An example:</p>\n<pre>\n"
                                        + kIss + "</pre>\n</body>\n</html>\n");
    QVERIFY(refreshAndWait(sources));
    ElementSetSourceStatus s = sources.status()[0];
    QVERIFY2(!s.fetched && s.fromCache && s.error.contains(QStringLiteral("HTML page")), qPrintable(describe(s)));
    QCOMPARE(s.setCount, 979);
    QCOMPARE(sources.sets().size(), 979);
    QCOMPARE(fileBytes(cacheFile), full);

    // The same set as plain text: it reads cleanly, but keeps 1 of 979.
    server.pages.insert("/amateur.txt", kIss);
    QVERIFY(refreshAndWait(sources));
    s = sources.status()[0];
    QVERIFY2(s.error.contains(QStringLiteral("of the 979 satellites in the cached copy")), qPrintable(describe(s)));
    QVERIFY(describe(s).contains(QStringLiteral("kept the cached copy (979 sets")));
    QCOMPARE(fileBytes(cacheFile), full);

    // The next start still has all of them.
    ElementSetSources next(f.cache.path());
    next.setUrls(sources.urls());
    QVERIFY(loadAndWait(next));
    QCOMPARE(next.sets().size(), 979);
}

void TestElementSetSources::cutOffAnswerDoesNotReplaceAFullCache()
{
    FullCache f;
    QVERIFY(f.fill());
    TinyHttpServer &server = f.server;
    ElementSetSources &sources = f.sources;
    const QByteArray &full = f.full;
    const QString &cacheFile = f.cacheFile;

    // Cut after 1200 bytes, with the close as the only end: a few sets read.
    TinyHttpAnswer cut;
    cut.body = full;
    cut.cutAfter = 1200;
    cut.length = TinyHttpAnswer::Length::UntilClose;
    server.answers.insert("/amateur.txt", cut);
    QVERIFY(refreshAndWait(sources));
    ElementSetSourceStatus s = sources.status()[0];
    QVERIFY2(!s.fetched && s.fromCache && s.error.contains(QStringLiteral("of the 979 satellites")),
             qPrintable(describe(s)));
    QCOMPARE(fileBytes(cacheFile), full);
    QCOMPARE(sources.sets().size(), 979);

    // Cut short of its Content-Length: the transfer itself failed.
    cut.length = TinyHttpAnswer::Length::Announced;
    server.answers.insert("/amateur.txt", cut);
    QVERIFY(refreshAndWait(sources));
    s = sources.status()[0];
    QVERIFY2(s.error.contains(QStringLiteral("closed the connection after 1200 of the %1 bytes").arg(full.size())),
             qPrintable(describe(s)));
    QCOMPARE(fileBytes(cacheFile), full);
    QCOMPARE(sources.sets().size(), 979);
}

void TestElementSetSources::fifoAndDeviceAsSourcesAreRefused()
{
    QTemporaryDir dir;
    const QString fifo = dir.filePath(QStringLiteral("sets.fifo"));
    QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
    ElementSetSources sources(dir.filePath(QStringLiteral("cache")));
    sources.setUrls({QUrl::fromLocalFile(fifo), QUrl::fromLocalFile(QStringLiteral("/dev/zero"))});
    // No writer ever comes to the FIFO, and /dev/zero never ends: both are
    // refused at once, and nothing waits meanwhile.
    QElapsedTimer clock;
    clock.start();
    QVERIFY(refreshAndWait(sources, 10000));
    QVERIFY(clock.elapsed() < 5000);
    const QList<ElementSetSourceStatus> status = sources.status();
    QVERIFY2(status[0].error.contains(QStringLiteral("FIFO")), qPrintable(describe(status[0])));
    QVERIFY2(status[1].error.contains(QStringLiteral("character device")), qPrintable(describe(status[1])));
    QVERIFY(status[0].error.contains(fifo));
    QVERIFY(sources.sets().isEmpty());
}

void TestElementSetSources::fifoAsCacheIsRefusedAtLoad()
{
    QTemporaryDir dir;
    ElementSetSources sources(dir.path());
    const QUrl url(QStringLiteral("http://127.0.0.1:1/amateur.txt"));
    sources.setUrls({url});
    QCOMPARE(::mkfifo(QFile::encodeName(sources.cacheFile(url)).constData(), 0600), 0);
    QVERIFY(loadAndWait(sources));
    const ElementSetSourceStatus s = sources.status()[0];
    QVERIFY2(s.error.contains(QStringLiteral("cached copy cannot be used")) && s.error.contains(QStringLiteral("FIFO")),
             qPrintable(describe(s)));
    QVERIFY(!s.fromCache);
}

void TestElementSetSources::parsingLeavesTheEventLoopFree()
{
    QTemporaryDir cache;
    TinyHttpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    const QByteArray big = manySets(90000); // about 13 MB, under the cap
    QVERIFY(big.size() < kMaxElementSetBytes);
    server.pages.insert("/big.txt", big);
    ElementSetSources sources(cache.path());
    sources.setUrls({server.url("/big.txt")});

    // A timer every 10 ms: the longest gap between its ticks is the longest
    // the event loop was held.
    QElapsedTimer sinceTick;
    qint64 longestGapMs = 0;
    int ticks = 0;
    QTimer ticker;
    ticker.setInterval(10);
    connect(&ticker, &QTimer::timeout, this, [&] {
        longestGapMs = std::max(longestGapMs, sinceTick.restart());
        ++ticks;
    });
    sinceTick.start();
    ticker.start();
    QElapsedTimer clock;
    clock.start();
    QVERIFY(refreshAndWait(sources, 60000));
    ticker.stop();
    qInfo("%d ticks in %lld ms, the longest gap %lld ms", ticks, qlonglong(clock.elapsed()), qlonglong(longestGapMs));
    QCOMPARE(sources.status()[0].setCount, 90000);
    // Parsing these on the test's thread holds it about 650 ms; a busy
    // machine may pause the thread for a while, never that long.
    QVERIFY2(longestGapMs < 300, qPrintable(QStringLiteral("the event loop was held %1 ms").arg(longestGapMs)));
}

QTEST_GUILESS_MAIN(TestElementSetSources)
#include "tst_elementsetsources.moc"
